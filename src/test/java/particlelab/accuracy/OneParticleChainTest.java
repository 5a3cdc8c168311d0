package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import org.junit.jupiter.api.Test;
import particlelab.physics.ParticleIntegrator;
import particlelab.physics.Particle;

/**
 * Why one particle under gravity + linear drag cannot take a shorter chain of operations per
 * step and stay the lecture's recipe: docs/speed.md ("One particle against the primitive loop
 * on this host") bounds the step by the recipe's four dependent operations on V,
 * {@code σ·V}, {@code g − σ·V}, {@code h·a}, {@code V + h·a}, each rounded to float. Every
 * shorter form changes the floats of some steps of the benchmark's flight
 * ({@link OneParticleMixScene}: launch at (20, 30, 4) m/s, 1000 steps of 1/60 s, b = 0.5 kg/s,
 * 1 kg); only the four operations in the recipe's order give the integrator's floats.
 */
class OneParticleChainTest {

    @Test
    void onlyTheRecipesFourRoundingsGiveTheIntegratorsVelocity() {
        ForceMix mix = ForceMix.LINEAR;
        ParticleIntegrator integrator = mix.integrator();
        Vector3f g = integrator.acceleration(new Particle(), new Vector3f());
        float h = 1f / 60f;
        float s = mix.linearDrag() / ForceMix.MASS_KG;
        float factor = 1f - h * s;
        float stepGx = h * g.x;
        float stepGy = h * g.y;
        float stepGz = h * g.z;
        Particle particle = new Particle();
        particle.velocity.set(20f, 30f, 4f);
        int recipeMisses = 0;
        int foldMisses = 0;
        int fusedMisses = 0;
        int doubleMisses = 0;
        float[] v = new float[3];
        float[] gravity = {g.x, g.y, g.z};
        float[] stepGravity = {stepGx, stepGy, stepGz};
        for (int n = 0; n < OneParticleMixScene.STEPS_PER_LAUNCH; ++n) {
            v[0] = particle.velocity.x;
            v[1] = particle.velocity.y;
            v[2] = particle.velocity.z;
            integrator.step(particle, h);
            float[] after = {particle.velocity.x, particle.velocity.y, particle.velocity.z};
            boolean recipe = true;
            boolean fold = true;
            boolean fused = true;
            boolean wide = true;
            for (int i = 0; i < 3; ++i) {
                // the recipe: four roundings in this order
                float a = gravity[i] - s * v[i];
                recipe &= Float.floatToRawIntBits(v[i] + h * a)
                        == Float.floatToRawIntBits(after[i]);
                // the fold (the primitive loop): two operations on V
                fold &= Float.floatToRawIntBits(v[i] * factor + stepGravity[i])
                        == Float.floatToRawIntBits(after[i]);
                // fused multiply-adds: two operations on V, each rounded once
                fused &= Float.floatToRawIntBits(Math.fma(h, Math.fma(-s, v[i], gravity[i]),
                        v[i])) == Float.floatToRawIntBits(after[i]);
                // the same four operations in double, rounded to float once
                wide &= Float.floatToRawIntBits((float) (v[i] + (double) h
                        * (gravity[i] - (double) s * v[i]))) == Float.floatToRawIntBits(after[i]);
            }
            recipeMisses += recipe ? 0 : 1;
            foldMisses += fold ? 0 : 1;
            fusedMisses += fused ? 0 : 1;
            doubleMisses += wide ? 0 : 1;
        }
        // Exact counts: float and double arithmetic are IEEE 754 in Java 17+ (strictfp by
        // default) and Math.fma rounds once by its specification, so these are the same on
        // every JVM; a change of the step's arithmetic changes them.
        assertEquals("recipe 0, fold 462, fused 17, double 16", "recipe " + recipeMisses
                + ", fold " + foldMisses + ", fused " + fusedMisses + ", double " + doubleMisses,
                "steps of the flight whose velocity differs from the integrator's");
    }
}
