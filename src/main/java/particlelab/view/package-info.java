/**
 * What the student sees of a simulation: trails, velocity arrows, the distance grid, camera
 * framing, and the HUD and help text; these read particle state and allocate nothing per frame.
 */
package particlelab.view;
