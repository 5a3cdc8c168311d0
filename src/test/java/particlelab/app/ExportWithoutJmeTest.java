package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code particle-lab demo NAME --frames N --export DIR} without {@code --screenshot} makes no
 * jME application: the command runs in a class loader of its own that defines the project's
 * and jME's classes itself, and afterwards that loader has never loaded jME's application
 * classes nor its context factory. (That the files are those the headless application wrote
 * is checked beside the application's start, in {@link ParticleLabAppStartTest}.)
 */
class ExportWithoutJmeTest {

    /** Classes a jME application or its context needs; the export loads none of them. */
    private static final String[] APPLICATION_CLASSES = {"com.jme3.app.LegacyApplication",
        "com.jme3.app.SimpleApplication", "com.jme3.system.JmeSystem",
        "com.jme3.system.JmeContext", "com.jme3.renderer.RenderManager",
        "particlelab.app.ParticleLabApp"};

    @Test
    void anExportWithoutScreenshotMakesNoJmeApplication(@TempDir Path folder)
            throws Exception {
        for (String demo : new String[] {"drag", "rotation"}) {
            Path into = folder.resolve(demo);
            IsolatingLoader loader = new IsolatingLoader(getClass().getClassLoader());
            Class<?> main = loader.loadClass("particlelab.app.Main");
            assertEquals(loader, main.getClassLoader(), "Main runs in the isolating loader");
            Method run = main.getMethod("run", String[].class, PrintStream.class,
                    PrintStream.class);
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            Object code = run.invoke(null, new String[] {"demo", demo, "--frames", "120",
                "--fixed-tpf", "0.016666668", "--export", into.toString(), "--print-command"},
                    new PrintStream(out, true, StandardCharsets.UTF_8),
                    new PrintStream(err, true, StandardCharsets.UTF_8));
            assertEquals(0, code, demo + ": " + out + err);
            assertTrue(out.toString(StandardCharsets.UTF_8).startsWith("csv "), out.toString());
            assertTrue(Files.list(into).count() >= 2, demo + ": a table and parameters.csv");
            // --print-command's check re-ran the 120 frames, without an application either
            assertTrue(out.toString(StandardCharsets.UTF_8).contains(
                    "state: step 120, t = 2.0000 s"), out.toString());
            assertTrue(out.toString(StandardCharsets.UTF_8).contains(
                    "the command re-run gives the same bits"), out.toString());
            // The demo's own classes were loaded here, so the check below means something.
            assertTrue(loader.hasLoaded("particlelab.demo.DemoState"), demo);
            assertTrue(loader.hasLoaded("com.jme3.math.Vector3f"), demo);
            List<String> loaded = new ArrayList<>();
            for (String name : APPLICATION_CLASSES) {
                if (loader.hasLoaded(name)) {
                    loaded.add(name);
                }
            }
            assertEquals(List.of(), loaded, demo + ": the export loaded jME's application");
        }
    }

    @Test
    void theIsolatingLoaderSeesAnApplicationWhereOneIsMade() throws Exception {
        // The check above can fail: the same loader, asked for the window's class, has it.
        IsolatingLoader loader = new IsolatingLoader(getClass().getClassLoader());
        assertFalse(loader.hasLoaded("com.jme3.app.LegacyApplication"));
        Class.forName("particlelab.app.ParticleLabApp", true, loader);
        assertTrue(loader.hasLoaded("com.jme3.app.LegacyApplication"));
    }

    /**
     * Defines the project's, jME's and Lemur's classes itself (so it knows which were loaded)
     * and leaves the JDK's and the test libraries' to its parent.
     */
    private static final class IsolatingLoader extends ClassLoader {

        IsolatingLoader(ClassLoader parent) {
            super(parent);
        }

        boolean hasLoaded(String name) {
            synchronized (getClassLoadingLock(name)) {
                return findLoadedClass(name) != null;
            }
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve)
                throws ClassNotFoundException {
            if (!name.startsWith("particlelab.") && !name.startsWith("com.jme3.")
                    && !name.startsWith("com.simsilica.")) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> found = findLoadedClass(name);
                if (found == null) {
                    String file = name.replace('.', '/') + ".class";
                    try (InputStream in = getParent().getResourceAsStream(file)) {
                        if (in == null) {
                            throw new ClassNotFoundException(name);
                        }
                        byte[] bytes = in.readAllBytes();
                        found = defineClass(name, bytes, 0, bytes.length);
                    } catch (IOException e) {
                        throw new ClassNotFoundException(name, e);
                    }
                }
                if (resolve) {
                    resolveClass(found);
                }
                return found;
            }
        }
    }
}
