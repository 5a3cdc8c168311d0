/**
 * The lecture's particle physics: particles, the forces a scene composes, the one shared Euler
 * integrator, the stepping clock that turns frame times into steps, and stability limits.
 * Imports only the JDK and {@code com.jme3.math}.
 */
package particlelab.physics;
