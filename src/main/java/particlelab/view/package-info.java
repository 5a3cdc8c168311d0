/**
 * What the student sees of a simulation: trails, velocity arrows, the distance grid, camera
 * framing, and the HUD and help text; and hears: the collision sounds, played through jME's
 * audio or, with no audio device, recorded and shown. These read the simulation's state and
 * allocate nothing per frame.
 */
package particlelab.view;
