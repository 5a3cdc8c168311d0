/**
 * Rigid bodies for the rotation demos: a rigid body is a particle (moved by the shared
 * {@code ParticleIntegrator}) plus an orientation matrix, an angular velocity, a principal
 * inertia and a torque, turned by the {@code RotationIntegrator}. Imports only
 * {@code particlelab.physics}, {@code com.jme3.math} and the JDK.
 */
package particlelab.rigid;
