package particlelab.accuracy;

/**
 * The report's own benchmarks, timed in this JVM one after another (side by side): every
 * stepper and the two references on one particle ({@link OneParticleScene}), then the bulk
 * forms for N particles ({@link BulkScene}), the same scenes and row names as the JMH
 * benchmarks. Both scenes relaunch on a schedule, so no state decays into subnormal floats.
 */
final class BenchmarkStudy {

    private BenchmarkStudy() {
    }

    static int units(ReportConfig config) {
        return Scheme.values().length + 2 + 4 * config.particleCounts().length;
    }

    static BenchmarkTable run(ReportConfig config, CostMeter meter, ProgressBar progress) {
        BenchmarkTable table = new BenchmarkTable();
        OneParticleScene scene = new OneParticleScene();
        int steps = OneParticleScene.STEPS_PER_LAUNCH;
        for (Scheme scheme : Scheme.values()) {
            progress.phase("benchmarks: " + scheme.id());
            Stepper stepper = scheme.create(scene.forces());
            add(table, scheme.id(), meter.measure(units -> scene.fly(stepper), steps));
            progress.advance();
        }
        progress.phase("benchmarks: lecture style and primitive loop");
        add(table, BenchmarkTable.LECTURE_STYLE,
                meter.measure(units -> scene.flyLectureStyle(), steps));
        progress.advance();
        add(table, BenchmarkTable.PRIMITIVE_LOOP,
                meter.measure(units -> scene.flyPrimitiveLoop(), steps));
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
