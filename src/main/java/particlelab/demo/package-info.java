/**
 * The demo framework: {@link particlelab.demo.DemoState}, the one base class a demo extends,
 * and its kit (particles, keys, parameters, the HUD's lines, the scene, exact ghosts,
 * exports). The demos themselves are in {@code particlelab.lecture}.
 */
package particlelab.demo;
