/**
 * The reference steppers the demos compare the lecture's step with (forward Euler, velocity
 * Verlet, midpoint, RK4, the exact drag step), the exact paths the ghosts draw, the slide's
 * listing as code and the in-process cost meter: what a demo may use of the accuracy work.
 * The report that measures and draws them is {@code accuracy}, which imports this package and
 * is imported by no demo. Imports {@code physics}, {@code world} (a path's state record) and
 * the JDK.
 */
package particlelab.reference;
