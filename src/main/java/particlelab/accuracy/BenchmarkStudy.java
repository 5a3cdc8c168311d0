package particlelab.accuracy;

import java.util.ArrayList;
import java.util.List;
import particlelab.physics.ParticleBatch;
import particlelab.reference.CostMeter;
import particlelab.reference.Scheme;
import particlelab.reference.Stepper;


/**
 * The report's own benchmarks, timed in this JVM one after another (side by side): every
 * stepper and the two references on one particle ({@link OneParticleScene}), then the bulk
 * forms for N particles ({@link BulkScene}), then every {@link ForceMix} on one particle
 * ({@link OneParticleMixScene}) and on N particles ({@link BulkScene}) along every path: the
 * same scenes and row names as the JMH benchmarks (the batch's Vector API form only where
 * this JVM has the API). Every scene relaunches on a schedule, so no
 * state decays into subnormal floats. {@link #rowNames} lists the rows a run writes.
 */
final class BenchmarkStudy {

    /** The paths of the one-particle mix rows, in the tables' order. */
    static final List<String> SINGLE_PATHS = List.of(BenchmarkTable.PATH_LECTURE,
            BenchmarkTable.PATH_OBJECTS, BenchmarkTable.PATH_PRIMITIVE);
    /** The paths of the N-particle mix rows, in the tables' order. */
    static final List<String> BULK_PATHS = List.of(BenchmarkTable.PATH_LECTURE,
            BenchmarkTable.PATH_OBJECTS, BenchmarkTable.PATH_BATCH,
            BenchmarkTable.PATH_PRIMITIVE);

    private BenchmarkStudy() {
    }

    static int units(ReportConfig config) {
        return rowNames(config).size();
    }

    /**
     * List the rows {@link #run} writes for a configuration, in order.
     *
     * @param config the report's size (not null)
     * @return a new list of row names
     */
    static List<String> rowNames(ReportConfig config) {
        List<String> names = new ArrayList<>();
        for (Scheme scheme : Scheme.values()) {
            names.add(scheme.id());
        }
        names.add(BenchmarkTable.LECTURE_STYLE);
        names.add(BenchmarkTable.PRIMITIVE_LOOP);
        for (int count : config.particleCounts()) {
            names.add(BenchmarkTable.bulkName(BenchmarkTable.BULK_LECTURE, count));
            names.add(BenchmarkTable.bulkName(BenchmarkTable.BULK_OBJECTS, count));
            names.add(BenchmarkTable.bulkName(BenchmarkTable.BULK_BATCH, count));
            names.add(BenchmarkTable.bulkName(BenchmarkTable.BULK_PRIMITIVE, count));
        }
        for (ForceMix mix : ForceMix.values()) {
            for (String path : SINGLE_PATHS) {
                names.add(BenchmarkTable.singleName(mix, path));
            }
            for (int count : config.particleCounts()) {
                for (String path : BULK_PATHS) {
                    names.add(BenchmarkTable.bulkName(mix, path, count));
                    if (path.equals(BenchmarkTable.PATH_BATCH) && hasVectorRows(mix)) {
                        names.add(BenchmarkTable.bulkName(mix,
                                BenchmarkTable.PATH_BATCH_VECTOR, count));
                    }
                }
            }
        }
        return names;
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
        for (ForceMix mix : ForceMix.values()) {
            mix(table, mix, config, meter, progress);
        }
        if (!names(table).equals(rowNames(config))) {
            throw new IllegalStateException("benchmark rows " + names(table)
                    + " differ from the promised " + rowNames(config));
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

    /** One mix: one particle along every path, then N particles along every path. */
    private static void mix(BenchmarkTable table, ForceMix mix, ReportConfig config,
            CostMeter meter, ProgressBar progress) {
        progress.phase("benchmarks: " + mix.id() + ", one particle");
        OneParticleMixScene one = new OneParticleMixScene(mix);
        int steps = OneParticleMixScene.STEPS_PER_LAUNCH;
        add(table, BenchmarkTable.singleName(mix, BenchmarkTable.PATH_LECTURE),
                meter.measure(units -> one.flyLectureStyle(), steps));
        progress.advance();
        add(table, BenchmarkTable.singleName(mix, BenchmarkTable.PATH_OBJECTS),
                meter.measure(units -> one.flySharedObjects(), steps));
        progress.advance();
        add(table, BenchmarkTable.singleName(mix, BenchmarkTable.PATH_PRIMITIVE),
                meter.measure(units -> one.flyPrimitiveLoop(), steps));
        progress.advance();
        for (int count : config.particleCounts()) {
            progress.phase("benchmarks: " + mix.id() + ", " + count + " particles");
            // the last scene's particles (up to 10^6 of each kind) are garbage now: collect
            // them here rather than inside a measured round
            System.gc();
            BulkScene scene = new BulkScene(mix, count);
            add(table, BenchmarkTable.bulkName(mix, BenchmarkTable.PATH_LECTURE, count),
                    meter.measure(units -> scene.stepLectureStyle(), count));
            progress.advance();
            add(table, BenchmarkTable.bulkName(mix, BenchmarkTable.PATH_OBJECTS, count),
                    meter.measure(units -> scene.stepSharedEach(), count));
            progress.advance();
            add(table, BenchmarkTable.bulkName(mix, BenchmarkTable.PATH_BATCH, count),
                    meter.measure(units -> scene.stepSharedBatch(), count));
            progress.advance();
            if (hasVectorRows(mix)) {
                String name = BenchmarkTable.bulkName(mix, BenchmarkTable.PATH_BATCH_VECTOR,
                        count);
                add(table, name, meter.measureOnceCompiled(
                        units -> scene.stepSharedBatchVector(), count));
                progress.advance();
            }
            add(table, BenchmarkTable.bulkName(mix, BenchmarkTable.PATH_PRIMITIVE, count),
                    meter.measure(units -> scene.stepPrimitiveLoop(), count));
            progress.advance();
        }
    }

    /** True if the mix's bulk rows include the Vector API form: it has one, the JVM too. */
    private static boolean hasVectorRows(ForceMix mix) {
        return mix.hasVectorBatch() && ParticleBatch.isVectorApiAvailable();
    }

    private static List<String> names(BenchmarkTable table) {
        List<String> names = new ArrayList<>();
        for (BenchmarkTable.Row row : table.rows()) {
            names.add(row.name());
        }
        return names;
    }

    private static void add(BenchmarkTable table, String name, CostMeter.Measurement measured) {
        table.add(new BenchmarkTable.Row(name, measured.nanosPerUnit(), measured.spread().min(),
                measured.spread().max(), measured.bytesPerUnit()));
    }
}
