/**
 * The lecture's demos, one class each, in the order of lecture 15: each extends
 * {@link particlelab.demo.DemoState} and reads like the lecture notes it shows (what to watch
 * for in its Javadoc, the slide's formulas in its HUD). The machinery they build on is in
 * {@code particlelab.demo}; a student's own demo goes here too, with one line in
 * {@code particlelab.app.DemoCatalog}.
 */
package particlelab.lecture;
