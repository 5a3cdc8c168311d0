package particlelab.demo;

import java.util.List;
import particlelab.physics.Particle;
import particlelab.physics.SimulationClock;
import particlelab.view.TextFormat;

/**
 * The part of a demo's HUD body that every demo shows: the equations it runs, the simulated
 * time, one line per particle (position, velocity, speed and where it landed), the stepping
 * line (fixed h or raw tpf, time scale, pause) and the stability line (the smallest limit and
 * the particle it belongs to). The demo's own lines follow, from
 * {@link DemoState#writeHudLines}. Writing allocates nothing.
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
        appendStabilityLine(text);
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
        if (clock.isPaused()) {
            text.append("   PAUSED (Space resumes, N steps)");
        }
        text.append('\n');
    }

    /**
     * The stability line: the smallest stability limit of the particles still moving, at their
     * current states, naming the particle it belongs to with its damping rate (lambda) and, for
     * a spring, its angular frequency omega = sqrt(k/m). Plain ASCII: the HUD font has no Greek.
     */
    private void appendStabilityLine(StringBuilder text) {
        float limit = Float.POSITIVE_INFINITY;
        DemoParticle limiting = null;
        int moving = 0;
        for (int i = 0; i < particles.size(); ++i) {
            DemoParticle particle = particles.get(i);
            if (particle.isHeld()) {
                continue;
            }
            ++moving;
            float particleLimit = particle.getIntegrator().maxStableStep(particle.getParticle());
            if (particleLimit < limit) {
                limit = particleLimit;
                limiting = particle;
            }
        }
        if (moving == 0) {
            text.append("Stability: nothing is moving, so no step limit applies\n");
            return;
        }
        if (limiting == null) {
            text.append("Stability: any h is stable (no drag or spring on a moving particle)\n");
            return;
        }
        Particle particle = limiting.getParticle();
        text.append("Stability: h < ");
        TextFormat.appendFixed(text, limit, 3).append(" s for '").append(limiting.getLabel())
                .append("' (lambda = ");
        TextFormat.appendFixed(text, limiting.getIntegrator().dampingRate(particle), 2)
                .append(" /s");
        float stiffness = limiting.getIntegrator().stiffness(particle);
        if (stiffness > 0f) {
            text.append(", omega = ");
            TextFormat.appendFixed(text, (float) Math.sqrt(stiffness), 2).append(" /s");
        }
        text.append(")\n");
    }
}
