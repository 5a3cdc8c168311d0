package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.lang.reflect.Modifier;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import particlelab.demo.DemoState;

class DemoCatalogTest {

    @Test
    void everyDemoClassIsInTheCatalogue() throws Exception {
        // The demo list is explicit; this scan (tests only) catches a demo left out of it.
        File directory = new File(DemoState.class.getProtectionDomain().getCodeSource()
                .getLocation().toURI()).toPath().resolve("particlelab/demo").toFile();
        Set<String> demoClasses = new TreeSet<>();
        for (String file : directory.list()) {
            if (!file.endsWith(".class") || file.contains("$")) {
                continue;
            }
            Class<?> type = Class.forName("particlelab.demo." + file.replace(".class", ""));
            if (DemoState.class.isAssignableFrom(type)
                    && !Modifier.isAbstract(type.getModifiers())) {
                demoClasses.add(type.getName());
            }
        }
        Set<String> catalogued = new TreeSet<>();
        for (DemoCatalog.Entry entry : DemoCatalog.entries()) {
            catalogued.add(entry.create().getClass().getName());
        }
        assertTrue(demoClasses.size() >= 6, demoClasses.toString());
        assertEquals(demoClasses, catalogued);
    }

    @Test
    void namesAreUniqueAndFoundByNameOrNumber() {
        List<String> names = DemoCatalog.names();
        assertEquals(names.size(), new HashSet<>(names).size());
        assertEquals(List.of("uniform", "pull", "drag", "thrust", "aiming", "wind"), names);
        assertEquals(4, DemoCatalog.indexOf("aiming"));
        assertEquals(4, DemoCatalog.indexOf("AIMING"));
        assertEquals(2, DemoCatalog.indexOf("3"));
        assertEquals(-1, DemoCatalog.indexOf("rotation"));
    }
}
