/**
 * Speed against error: reference steppers (forward Euler, velocity Verlet, midpoint, RK4, the
 * exact step) beside the shared Euler integrator, their errors, orders, stability limits and
 * costs, the overlap and swept collision tests measured in the world, and the report that
 * draws them. For comparison only: the demos keep the lecture's Euler step. Imports
 * {@code physics}, {@code aiming}, {@code world} and {@code collision}, the JDK and, for plots,
 * XChart.
 */
package particlelab.accuracy;
