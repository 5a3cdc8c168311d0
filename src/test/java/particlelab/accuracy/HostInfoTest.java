package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The host block every speed figure is named with. */
class HostInfoTest {

    @Test
    void cpuModelIsTheFirstModelNameLine() {
        String cpuinfo = "processor\t: 0\nvendor_id\t: AuthenticAMD\n"
                + "model name\t: AMD EPYC 9R14 96-Core Processor\nprocessor\t: 1\n"
                + "model name\t: AMD EPYC 9R14 96-Core Processor\n";
        assertEquals("AMD EPYC 9R14 96-Core Processor", HostInfo.cpuModel(cpuinfo));
        assertEquals("ARMv7 Processor rev 4 (v7l)",
                HostInfo.cpuModel("Processor\t: ARMv7 Processor rev 4 (v7l)\n"));
        assertEquals("unknown", HostInfo.cpuModel(""));
        assertEquals("unknown", HostInfo.cpuModel("model name\t:   \n"));
    }

    @Test
    void memoryIsMemTotalInGibibytes() {
        assertEquals("23.5 GiB", HostInfo.memory("MemTotal:       24683664 kB\nMemFree: 1 kB\n"));
        assertEquals("unknown", HostInfo.memory("MemFree: 1 kB\n"));
        assertEquals("unknown", HostInfo.memory("MemTotal: lots\n"));
    }

    @Test
    void cachesAreListedByLevelAndType(@TempDir Path cpu) throws IOException {
        cache(cpu, 0, "1", "Data", "32K");
        cache(cpu, 1, "1", "Instruction", "32K");
        cache(cpu, 2, "2", "Unified", "1024K");
        cache(cpu, 3, "3", "Unified", "32768K");
        assertEquals("L1d 32K, L1i 32K, L2 1024K, L3 32768K", HostInfo.caches(cpu));
        assertEquals("unknown", HostInfo.caches(cpu.resolve("missing")));
    }

    @Test
    void theBlockNamesEveryField() {
        String block = HostInfo.now().block();
        for (String field : new String[] {"- CPU: ", "- cores: ", "- caches: ", "- memory: ",
            "- JDK: ", "- collector: ", "- load average (1 min): "}) {
            assertTrue(block.contains(field), field + " missing from\n" + block);
        }
        assertTrue(block.contains(System.getProperty("java.version")), block);
        assertTrue(block.contains(" at start, ") && block.endsWith(" at end\n"), block);
    }

    private static void cache(Path cpu, int index, String level, String type, String size)
            throws IOException {
        Path folder = Files.createDirectories(cpu.resolve("index" + index));
        Files.write(folder.resolve("level"), (level + "\n").getBytes(StandardCharsets.UTF_8));
        Files.write(folder.resolve("type"), (type + "\n").getBytes(StandardCharsets.UTF_8));
        Files.write(folder.resolve("size"), (size + "\n").getBytes(StandardCharsets.UTF_8));
    }
}
