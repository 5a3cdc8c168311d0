package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;
import particlelab.lecture.UniformMotionDemo;

class DemoCatalogTest {

    /**
     * The demo list is explicit; this scan of the compiled lecture package (tests only)
     * catches a concrete {@link DemoState} left out of it, or listed twice. It checks that
     * every demo is listed, not what else the list holds, so a student's new demo needs no
     * change here. The framework package holds no demo: the demos are in one place.
     *
     * @throws Exception if the compiled classes cannot be listed or loaded
     */
    @Test
    void everyDemoClassIsInTheCatalogueAndInTheLecturePackage() throws Exception {
        Set<String> demoClasses = concreteDemos("particlelab.lecture");
        List<String> catalogued = new ArrayList<>();
        for (DemoCatalog.Entry entry : DemoCatalog.entries()) {
            catalogued.add(entry.create().getClass().getName());
        }
        // The scan sees the package (a scan that finds nothing would prove nothing).
        assertTrue(demoClasses.contains(UniformMotionDemo.class.getName()),
                demoClasses.toString());
        assertEquals(catalogued.size(), new HashSet<>(catalogued).size(),
                "a demo class listed twice: " + catalogued);
        Set<String> missing = new TreeSet<>(demoClasses);
        missing.removeAll(catalogued);
        assertTrue(missing.isEmpty(), "add to DemoCatalog's list: " + missing);
        assertEquals(Set.of(), concreteDemos("particlelab.demo"),
                "a demo in the framework's package: move it to particlelab.lecture");
    }

    private static Set<String> concreteDemos(String packageName) throws Exception {
        File directory = new File(DemoState.class.getProtectionDomain().getCodeSource()
                .getLocation().toURI()).toPath().resolve(packageName.replace('.', '/'))
                .toFile();
        Set<String> demoClasses = new TreeSet<>();
        for (String file : directory.list()) {
            if (!file.endsWith(".class") || file.contains("$")) {
                continue;
            }
            Class<?> type = Class.forName(packageName + "." + file.replace(".class", ""));
            if (DemoState.class.isAssignableFrom(type)
                    && !Modifier.isAbstract(type.getModifiers())) {
                demoClasses.add(type.getName());
            }
        }
        return demoClasses;
    }

    @Test
    void everyNameIsUniqueAndFoundByNameAnyCaseOrNumber() {
        List<String> names = DemoCatalog.names();
        assertFalse(names.isEmpty());
        assertEquals(names.size(), new HashSet<>(names).size(), names.toString());
        for (int i = 0; i < names.size(); ++i) {
            String name = names.get(i);
            assertTrue(name.matches("\\S+"), "a command-line name needs no quotes: '" + name
                    + "'");
            assertEquals(i, DemoCatalog.indexOf(name), name);
            assertEquals(i, DemoCatalog.indexOf(name.toUpperCase(Locale.ROOT)), name);
            assertEquals(i, DemoCatalog.indexOf(Integer.toString(i + 1)), name);
        }
        assertEquals(-1, DemoCatalog.indexOf(Integer.toString(names.size() + 1)));
        assertEquals(-1, DemoCatalog.indexOf("0"));
        // Only the number's plain form names a demo, as the digit keys and --demo write it.
        assertEquals(-1, DemoCatalog.indexOf("01"));
        assertEquals(-1, DemoCatalog.indexOf("+1"));
        assertEquals(-1, DemoCatalog.indexOf(" 1"));
        assertEquals(-1, DemoCatalog.indexOf(""));
        assertEquals(-1, DemoCatalog.indexOf(null));
        assertEquals(-1, DemoCatalog.indexOf("no such demo"));
    }

    /**
     * Each entry knows the class of the demos it creates, so the entry of a demo shown (the
     * share key C, every press) is found by its class, with no demo created to compare with.
     */
    @Test
    void aDemosEntryIsFoundByItsClassWithoutCreatingOne() {
        List<DemoCatalog.Entry> entries = DemoCatalog.entries();
        List<DemoState> demos = DemoCatalog.createAll();
        for (int i = 0; i < entries.size(); ++i) {
            assertEquals(entries.get(i).getType(), demos.get(i).getClass(),
                    entries.get(i).getName());
            assertEquals(i, DemoCatalog.indexOfDemo(demos.get(i)), entries.get(i).getName());
        }
        // A demo of no entry's class (a student's, not listed yet) has no place.
        assertEquals(-1, DemoCatalog.indexOfDemo(new DemoState("not listed") {
            @Override
            protected void createScene() {
            }
        }));
    }

    /**
     * {@code --particles N} reaches the one demo that takes a count (the fountain) through
     * the catalogue, with no cast in the command; every other demo is made as by name.
     */
    @Test
    void aParticleCountReachesOnlyTheDemoThatTakesOne() {
        String counted = DemoCatalog.nameWithParticleCount();
        assertEquals("fountain", counted);
        List<DemoState> demos = DemoCatalog.createAll(2000);
        List<DemoState> plain = DemoCatalog.createAll();
        for (int i = 0; i < demos.size(); ++i) {
            boolean takesCount = DemoCatalog.entries().get(i).hasParticleCount();
            assertEquals(i == DemoCatalog.indexOf(counted), takesCount, demos.get(i).getTitle());
            assertEquals(takesCount ? 2000 : plain.get(i).getRun().countSimulatedParticles(),
                    demos.get(i).getRun().countSimulatedParticles(), demos.get(i).getTitle());
        }
    }
}
