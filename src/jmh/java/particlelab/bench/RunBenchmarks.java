package particlelab.bench;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import org.openjdk.jmh.infra.BenchmarkParams;
import org.openjdk.jmh.profile.GCProfiler;
import org.openjdk.jmh.results.Result;
import org.openjdk.jmh.results.RunResult;
import org.openjdk.jmh.runner.Runner;
import org.openjdk.jmh.runner.options.CommandLineOptions;
import org.openjdk.jmh.runner.options.OptionsBuilder;
import org.openjdk.jmh.runner.options.TimeValue;
import particlelab.accuracy.BenchmarkTable;
import particlelab.accuracy.ForceMix;

/**
 * Runs the benchmarks the way {@code org.openjdk.jmh.Main} does (it takes the same options),
 * adds modest defaults and JMH's gc profiler, and writes the results as the report's
 * {@code benchmarks.csv}.
 *
 * <p>Defaults, each overridden by the matching JMH option: 1 fork, 2 warm-up iterations of
 * 1 s, 3 measured iterations of 1 s, all benchmarks of this package: about three minutes on
 * 2 cores. Usage: {@code RunBenchmarks [--csv=FILE] [JMH options]}.
 */
public final class RunBenchmarks {

    private static final String CSV_OPTION = "--csv=";
    private static final String ALLOCATION_KEY = "gc.alloc.rate.norm";

    private RunBenchmarks() {
    }

    /**
     * Run the benchmarks.
     *
     * @param args {@code --csv=FILE} (default build/reports/jmh/benchmarks.csv) then JMH
     *     options
     * @throws Exception if JMH fails or the CSV cannot be written
     */
    public static void main(String[] args) throws Exception {
        Path csv = Paths.get("build", "reports", "jmh", "benchmarks.csv");
        List<String> jmhArgs = new ArrayList<>();
        for (String arg : args) {
            if (arg.startsWith(CSV_OPTION)) {
                csv = Paths.get(arg.substring(CSV_OPTION.length()));
            } else {
                jmhArgs.add(arg);
            }
        }
        CommandLineOptions given = new CommandLineOptions(jmhArgs.toArray(new String[0]));
        OptionsBuilder options = new OptionsBuilder();
        options.parent(given);
        if (given.getIncludes().isEmpty()) {
            options.include(RunBenchmarks.class.getPackage().getName() + ".*");
        }
        if (!given.getForkCount().hasValue()) {
            options.forks(1);
        }
        if (!given.getWarmupIterations().hasValue()) {
            options.warmupIterations(2);
        }
        if (!given.getWarmupTime().hasValue()) {
            options.warmupTime(TimeValue.seconds(1));
        }
        if (!given.getMeasurementIterations().hasValue()) {
            options.measurementIterations(3);
        }
        if (!given.getMeasurementTime().hasValue()) {
            options.measurementTime(TimeValue.seconds(1));
        }
        if (given.getProfilers().isEmpty()) {
            options.addProfiler(GCProfiler.class);
        }
        Collection<RunResult> results = new Runner(options.build()).run();
        toTable(results).write(csv);
        System.out.println("Wrote " + csv.toAbsolutePath());
    }

    private static BenchmarkTable toTable(Collection<RunResult> results) {
        BenchmarkTable table = new BenchmarkTable();
        for (RunResult result : results) {
            BenchmarkParams params = result.getParams();
            String method = params.getBenchmark().substring(
                    params.getBenchmark().lastIndexOf('.') + 1);
            double nanos = result.getPrimaryResult().getScore();
            double bytes = allocation(result.getSecondaryResults());
            String particles = params.getParam("particles");
            if (particles != null) {
                // one invocation steps all N: per particle-step
                nanos /= Integer.parseInt(particles);
                bytes /= Integer.parseInt(particles);
            }
            table.add(new BenchmarkTable.Row(rowName(method, params.getParam("mix"),
                    particles), nanos, bytes));
        }
        return table;
    }

    /**
     * Name a result as the report names its rows. With a force mix ({@link MixBenchmark}):
     * {@code singlePath} → {@code single/<mix>/<path>}, {@code bulkPath} with N →
     * {@code bulk/<mix>/<path>/<N>}, {@code objectsPath} → {@code bulk/<mix>/<path>/1000};
     * without one: {@code bulk/<kebab>/<N>} or the kebab-case method name.
     */
    static String rowName(String method, String mix, String particles) {
        if (mix == null) {
            return particles == null ? kebab(method)
                    : BenchmarkTable.bulkName(kebab(method), Integer.parseInt(particles));
        }
        int split = 0;
        while (split < method.length() && !Character.isUpperCase(method.charAt(split))) {
            ++split;
        }
        String scope = method.substring(0, split);
        String path = kebab(method.substring(split)).replaceFirst("^-", "");
        ForceMix forces = ForceMix.named(mix);
        if (particles != null) {
            return BenchmarkTable.bulkName(forces, path, Integer.parseInt(particles));
        }
        if (scope.equals("objects")) {
            return BenchmarkTable.bulkName(forces, path, MixBenchmark.OBJECTS);
        }
        return BenchmarkTable.singleName(forces, path);
    }

    private static double allocation(Map<String, Result> secondary) {
        for (Map.Entry<String, Result> entry : secondary.entrySet()) {
            if (entry.getKey().endsWith(ALLOCATION_KEY)) {
                return entry.getValue().getScore();
            }
        }
        return Double.NaN;
    }

    /** {@code semiImplicitEuler} → {@code semi-implicit-euler}; {@code rk4} stays. */
    private static String kebab(String camel) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < camel.length(); ++i) {
            char c = camel.charAt(i);
            if (Character.isUpperCase(c)) {
                text.append('-').append(Character.toLowerCase(c));
            } else {
                text.append(c);
            }
        }
        return text.toString();
    }
}
