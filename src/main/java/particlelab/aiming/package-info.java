/**
 * Ballistics for HelloAiming: the lecture's level-target formula, its correction for the stepped
 * Euler bullet, the two-angle solution at a fixed launch speed, and iterative shoot-and-adjust
 * aiming that simulates shots with the shared integrator and the scene's own forces (by one of
 * several strategies, each attempt logged), the predictor-mismatch miss, and the hitscan cheat
 * for fast bullets against a stepped projectile.
 */
package particlelab.aiming;
