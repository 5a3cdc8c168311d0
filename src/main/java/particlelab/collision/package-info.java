/**
 * Collision detection for the shapes the scenes need, both of the lecture's approaches: the
 * overlap test at the end of a step and the intersection (swept) test over the step, for
 * spheres against static surfaces (planes, thin walls) and against each other. Pure geometry:
 * imports only the JDK and {@code com.jme3.math}.
 */
package particlelab.collision;
