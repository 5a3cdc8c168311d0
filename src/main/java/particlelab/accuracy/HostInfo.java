package particlelab.accuracy;

import java.io.IOException;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.OperatingSystemMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The machine a speed figure was measured on, named beside the figure: a ratio measured on one
 * processor is a property of that processor as much as of the code (a speed target met on one
 * host has been missed on another). Reads the CPU
 * model and caches where Linux publishes them ({@code /proc/cpuinfo}, {@code /sys/devices}),
 * and the rest from the JVM; what it cannot read it says is unknown.
 */
public final class HostInfo {

    private static final Path CPUINFO = Paths.get("/proc/cpuinfo");
    private static final Path MEMINFO = Paths.get("/proc/meminfo");
    private static final Path CACHES = Paths.get("/sys/devices/system/cpu/cpu0/cache");
    private static final String UNKNOWN = "unknown";

    private final String cpu;
    private final String caches;
    private final String memory;
    private final double loadAtStart;

    private HostInfo(String cpu, String caches, String memory, double loadAtStart) {
        this.cpu = cpu;
        this.caches = caches;
        this.memory = memory;
        this.loadAtStart = loadAtStart;
    }

    /**
     * Read this machine now; its load average now is the block's load at start.
     *
     * @return the host as this JVM sees it
     */
    public static HostInfo now() {
        return new HostInfo(cpuModel(read(CPUINFO)), caches(CACHES), memory(read(MEMINFO)),
                loadAverage());
    }

    /**
     * The host block, a Markdown list; the load average is given at start and now.
     *
     * @return lines "- CPU: …", "- cores: …", "- caches: …", "- memory: …", "- JDK: …",
     *     "- collector: …", "- load average (1 min): … at start, … at end"
     */
    public String block() {
        StringBuilder out = new StringBuilder();
        out.append("- CPU: ").append(cpu).append(" (").append(System.getProperty("os.arch"))
                .append(", ").append(System.getProperty("os.name")).append(")\n");
        out.append("- cores: ").append(Runtime.getRuntime().availableProcessors())
                .append(" seen by the JVM\n");
        out.append("- caches: ").append(caches).append('\n');
        out.append("- memory: ").append(memory).append('\n');
        out.append("- JDK: ").append(System.getProperty("java.vm.vendor")).append(' ')
                .append(System.getProperty("java.vm.name")).append(' ')
                .append(System.getProperty("java.version")).append('\n');
        out.append("- collector: ").append(collectors()).append('\n');
        out.append("- load average (1 min): ").append(load(loadAtStart)).append(" at start, ")
                .append(load(loadAverage())).append(" at end\n");
        return out.toString();
    }

    /** @return the CPU model's name, or "unknown" */
    public String cpu() {
        return cpu;
    }

    /**
     * The CPU's model from the text of {@code /proc/cpuinfo}.
     *
     * @param cpuinfo the file's text (may be empty)
     * @return the first "model name" value, else the first "Processor" or "cpu model" value,
     *     else "unknown"
     */
    static String cpuModel(String cpuinfo) {
        for (String key : new String[] {"model name", "Processor", "cpu model"}) {
            for (String line : cpuinfo.split("\n")) {
                int colon = line.indexOf(':');
                if (colon > 0 && line.substring(0, colon).trim().equals(key)) {
                    String value = line.substring(colon + 1).trim();
                    if (!value.isEmpty()) {
                        return value;
                    }
                }
            }
        }
        return UNKNOWN;
    }

    /**
     * The total memory from the text of {@code /proc/meminfo}.
     *
     * @param meminfo the file's text (may be empty)
     * @return e.g. "23.5 GiB", or "unknown"
     */
    static String memory(String meminfo) {
        for (String line : meminfo.split("\n")) {
            if (line.startsWith("MemTotal:")) {
                String[] words = line.substring("MemTotal:".length()).trim().split("\\s+");
                try {
                    double kib = Double.parseDouble(words[0]);
                    return String.format(Locale.ROOT, "%.1f GiB", kib / (1024.0 * 1024.0));
                } catch (NumberFormatException e) {
                    return UNKNOWN;
                }
            }
        }
        return UNKNOWN;
    }

    /**
     * The caches of one CPU, from a folder laid out as Linux's {@code cpu0/cache}: one
     * {@code indexN} folder a cache with files {@code level}, {@code type} and {@code size}.
     *
     * @param folder the folder (need not exist)
     * @return e.g. "L1d 32K, L1i 32K, L2 1024K, L3 32768K", or "unknown"
     */
    static String caches(Path folder) {
        List<String> found = new ArrayList<>();
        for (int index = 0; index < 16; ++index) {
            Path cache = folder.resolve("index" + index);
            if (!Files.isDirectory(cache)) {
                break;
            }
            String level = read(cache.resolve("level")).trim();
            String type = read(cache.resolve("type")).trim();
            String size = read(cache.resolve("size")).trim();
            if (level.isEmpty() || size.isEmpty()) {
                continue;
            }
            String suffix = type.equals("Data") ? "d" : type.equals("Instruction") ? "i" : "";
            found.add("L" + level + suffix + " " + size);
        }
        return found.isEmpty() ? UNKNOWN : String.join(", ", found);
    }

    private static String collectors() {
        List<String> names = new ArrayList<>();
        for (GarbageCollectorMXBean collector : ManagementFactory.getGarbageCollectorMXBeans()) {
            names.add(collector.getName());
        }
        return names.isEmpty() ? UNKNOWN : String.join(", ", names);
    }

    private static double loadAverage() {
        OperatingSystemMXBean os = ManagementFactory.getOperatingSystemMXBean();
        return os.getSystemLoadAverage();
    }

    private static String load(double average) {
        return average < 0.0 ? "not available"
                : String.format(Locale.ROOT, "%.2f", average);
    }

    private static String read(Path file) {
        try {
            return new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
        } catch (IOException | SecurityException e) {
            return "";
        }
    }
}
