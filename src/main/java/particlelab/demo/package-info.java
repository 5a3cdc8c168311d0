/**
 * The lecture's demos: {@link particlelab.demo.DemoState}, the one base class a demo extends,
 * and one class per demo, each reading like the lecture notes it shows.
 */
package particlelab.demo;
