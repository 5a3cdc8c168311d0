package particlelab.accuracy;

import com.jme3.math.Vector3f;
import particlelab.physics.Gravity;

/**
 * The report's own benchmarks, timed in this JVM one after another (side by side): every
 * stepper and the two references on one particle, then the bulk forms for N particles. Gravity
 * plus linear drag b/m = 0.5/s, h = 1/60 s, as in the JMH benchmarks, with the same row names.
 */
final class BenchmarkStudy {

    private static final double LINEAR_RATE = 0.5;
    private static final float STEP_FLOAT = 1f / 60f;
    private static final int STEPS_PER_CALL = 2000;

    private BenchmarkStudy() {
    }

    static int units(ReportConfig config) {
        return Scheme.values().length + 2 + 4 * config.particleCounts().length;
    }

    static BenchmarkTable run(ReportConfig config, CostMeter meter, ProgressBar progress) {
        BenchmarkTable table = new BenchmarkTable();
        ForceModel forces = ForceModel.perUnitMass(CanonicalCase.G, LINEAR_RATE, 0.0, 0.0);
        MotionState launch = CanonicalCase.launch();
        for (Scheme scheme : Scheme.values()) {
            progress.phase("benchmarks: " + scheme.id());
            Stepper stepper = scheme.create(forces);
            MotionState state = new MotionState();
            add(table, scheme.id(), meter.measure(units -> {
                state.set(launch);
                stepper.advance(state, WorkPrecisionStudy.TIMING_STEP_SECONDS, units);
                return state;
            }, STEPS_PER_CALL));
            progress.advance();
        }
        progress.phase("benchmarks: lecture style and primitive loop");
        Vector3f gravity = new Vector3f(0f, -Gravity.STANDARD_G, 0f);
        float[] gravityPerAxis = {0f, -Gravity.STANDARD_G, 0f};
        add(table, BenchmarkTable.LECTURE_STYLE, meter.measure(units -> {
            LectureStyleParticle particle =
                    new LectureStyleParticle(new Vector3f(), new Vector3f(20f, 30f, 0f), 1f);
            for (int n = 0; n < units; ++n) {
                particle.step(gravity, (float) LINEAR_RATE, STEP_FLOAT);
            }
            return particle;
        }, STEPS_PER_CALL));
        progress.advance();
        float[] position = new float[3];
        float[] velocity = new float[3];
        add(table, BenchmarkTable.PRIMITIVE_LOOP, meter.measure(units -> {
            velocity[0] = 20f;
            velocity[1] = 30f;
            PrimitiveLoop.stepOne(position, velocity, gravityPerAxis, (float) LINEAR_RATE,
                    STEP_FLOAT, units);
            return position;
        }, STEPS_PER_CALL));
        progress.advance();
        for (int count : config.particleCounts()) {
            bulk(table, count, meter, progress);
        }
        return table;
    }

    private static void bulk(BenchmarkTable table, int count, CostMeter meter,
            ProgressBar progress) {
        progress.phase("benchmarks: " + count + " particles");
        BulkScene scene = new BulkScene(count);
        add(table, BenchmarkTable.bulkName(BenchmarkTable.BULK_LECTURE, count),
                meter.measure(units -> scene.stepLectureStyle(), count));
        progress.advance();
        add(table, BenchmarkTable.bulkName(BenchmarkTable.BULK_OBJECTS, count),
                meter.measure(units -> scene.stepSharedObjects(), count));
        progress.advance();
        add(table, BenchmarkTable.bulkName(BenchmarkTable.BULK_BATCH, count),
                meter.measure(units -> scene.stepSharedBatch(), count));
        progress.advance();
        add(table, BenchmarkTable.bulkName(BenchmarkTable.BULK_PRIMITIVE, count),
                meter.measure(units -> scene.stepPrimitiveLoop(), count));
        progress.advance();
    }

    private static void add(BenchmarkTable table, String name, CostMeter.Measurement measured) {
        table.add(new BenchmarkTable.Row(name, measured.nanosPerUnit(), measured.bytesPerUnit()));
    }
}
