/**
 * The simulation world of one scene: its bodies, collision rules and listeners, and the one
 * {@code step(h)} that integrates every body with the shared Euler step and then runs the
 * lecture's collision pipeline (detect, prologue, resolve, epilogue). The demos, the command
 * line and the tests all step through it. Imports only {@code particlelab.physics},
 * {@code particlelab.collision}, {@code com.jme3.math} and the JDK.
 */
package particlelab.world;
