package particlelab.demo;

import java.util.List;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * The part of a demo's HUD body that every demo shows: the equations it runs, the simulated
 * time, one line per particle (position, velocity, speed and where it landed) and the stepping
 * line (fixed h or raw tpf, time scale, the stability limit, pause). The demo's own lines
 * follow, from {@link DemoState#writeHudLines}. Writing allocates nothing.
 */
final class HudWriter {

    private final SimulationClock clock;
    private final List<DemoParticle> particles;
    private String equations = "";

    /**
     * Create a writer for one demo.
     *
     * @param clock the demo's clock (not null, not modified)
     * @param particles the demo's particles (not null, live, not modified)
     */
    HudWriter(SimulationClock clock, List<DemoParticle> particles) {
        this.clock = clock;
        this.particles = particles;
    }

    /**
     * Set the equations shown at the top, one line each.
     *
     * @param text the lines, each ending in a newline (not null)
     */
    void setEquations(String text) {
        equations = text;
    }

    /**
     * Write the shared body text into storeResult, without allocating.
     *
     * @param storeResult storage for the text (not null, cleared and modified)
     * @return storeResult
     */
    StringBuilder write(StringBuilder storeResult) {
        StringBuilder text = storeResult;
        text.setLength(0);
        text.append(equations);
        text.append("t = ");
        TextFormat.appendFixed(text, clock.getSimulatedSeconds(), 2).append(" s\n");
        for (int i = 0; i < particles.size(); ++i) {
            appendParticleLine(text, particles.get(i));
        }
        appendSteppingLine(text);
        return text;
    }

    private static void appendParticleLine(StringBuilder text, DemoParticle demoParticle) {
        Particle particle = demoParticle.getParticle();
        text.append(demoParticle.getLabel()).append(":  P = ");
        TextFormat.appendVector(text, particle.position, 2).append(" m   V = ");
        TextFormat.appendVector(text, particle.velocity, 2).append(" m/s   |V| = ");
        TextFormat.appendFixed(text, particle.velocity.length(), 2).append(" m/s");
        if (demoParticle.hasLanded()) {
            text.append("   landed at x = ");
            TextFormat.appendFixed(text, demoParticle.getLandingX(), 2).append(" m");
        }
        text.append('\n');
    }

    private void appendSteppingLine(StringBuilder text) {
        text.append("Stepping: ");
        if (clock.getMode() == SimulationClock.Mode.FIXED_STEP) {
            text.append("fixed h = ");
            TextFormat.appendFixed(text, clock.getStepSeconds() * 1000f, 1).append(" ms");
        } else {
            text.append("raw tpf, last h = ");
            TextFormat.appendFixed(text, clock.getCurrentStepSeconds() * 1000f, 1)
                    .append(" ms");
        }
        text.append("   time x");
        TextFormat.appendFixed(text, clock.getTimeScale(), 2);
        float limit = Float.POSITIVE_INFINITY;
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            limit = Math.min(limit, particle.getIntegrator().maxStableStep(
                    particle.getParticle()));
        }
        if (limit < Float.POSITIVE_INFINITY) {
            text.append("   stable while h < ");
            TextFormat.appendFixed(text, limit, 3).append(" s");
        } else {
            text.append("   no drag: any h is stable");
        }
        if (clock.isPaused()) {
            text.append("   PAUSED (Space resumes, N steps)");
        }
        text.append('\n');
    }
}
