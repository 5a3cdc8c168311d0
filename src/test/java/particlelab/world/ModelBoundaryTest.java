package particlelab.world;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The model packages stay free of jME's scene graph: a plain source scan, no library. Files
 * under physics/, world/, collision/, aiming/ and rigid/ may import only com.jme3.math from jME.
 */
class ModelBoundaryTest {

    private static final Path SOURCES = Paths.get("src", "main", "java", "particlelab");
    private static final String[] MODEL_PACKAGES =
            {"physics", "world", "collision", "aiming", "rigid"};
    private static final Pattern JME_IMPORT =
            Pattern.compile("^\\s*import\\s+(static\\s+)?(com\\.jme3\\.[\\w.*]+)\\s*;",
                    Pattern.MULTILINE);

    @Test
    void modelPackagesImportOnlyJmeMaths() throws IOException {
        List<String> offences = new ArrayList<>();
        int files = 0;
        for (String name : MODEL_PACKAGES) {
            Path folder = SOURCES.resolve(name);
            assertTrue(Files.isDirectory(folder), folder + " must exist (run from the project)");
            try (Stream<Path> paths = Files.walk(folder)) {
                for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))
                        ::iterator) {
                    ++files;
                    Matcher imports = JME_IMPORT.matcher(Files.readString(file));
                    while (imports.find()) {
                        if (!imports.group(2).startsWith("com.jme3.math.")) {
                            offences.add(file + ": " + imports.group(2));
                        }
                    }
                }
            }
        }
        assertTrue(files > 20, "scanned only " + files + " files");
        assertEquals(List.of(), offences);
    }

    @Test
    void rigidBodiesImportNoModelPackageButPhysics() throws IOException {
        Pattern projectImport = Pattern.compile(
                "^\\s*import\\s+(static\\s+)?particlelab\\.(\\w+)", Pattern.MULTILINE);
        List<String> offences = new ArrayList<>();
        try (Stream<Path> paths = Files.walk(SOURCES.resolve("rigid"))) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))
                    ::iterator) {
                Matcher imports = projectImport.matcher(Files.readString(file));
                while (imports.find()) {
                    if (!"physics".equals(imports.group(2))) {
                        offences.add(file + ": particlelab." + imports.group(2));
                    }
                }
            }
        }
        assertEquals(List.of(), offences);
    }

    @Test
    void theScanCatchesASceneGraphImport() {
        Matcher imports = JME_IMPORT.matcher("package x;\nimport com.jme3.scene.Node;\n");
        assertTrue(imports.find());
        assertEquals("com.jme3.scene.Node", imports.group(2));
    }
}
