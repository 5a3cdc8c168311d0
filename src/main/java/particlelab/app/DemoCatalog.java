package particlelab.app;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import particlelab.demo.DemoState;
import particlelab.lecture.AnyHeightDemo;
import particlelab.lecture.BounceDemo;
import particlelab.lecture.ClipResponseDemo;
import particlelab.lecture.CollisionsDemo;
import particlelab.lecture.DragDemo;
import particlelab.lecture.FastBulletsDemo;
import particlelab.lecture.FountainDemo;
import particlelab.lecture.GravitationalPullDemo;
import particlelab.lecture.HelloAimingDemo;
import particlelab.lecture.IterativeAimingDemo;
import particlelab.lecture.RotationDemo;
import particlelab.lecture.SpinThrowDemo;
import particlelab.lecture.SpringDemo;
import particlelab.lecture.TargetsDemo;
import particlelab.lecture.TennisRacketDemo;
import particlelab.lecture.ThrustDemo;
import particlelab.lecture.TunnellingDemo;
import particlelab.lecture.UniformMotionDemo;
import particlelab.lecture.WindDemo;

/**
 * The demos, in lecture order: an explicit list, not a classpath scan. A new demo is added
 * here with a short command-line name; a test fails if a demo class is missing.
 */
public final class DemoCatalog {

    /** One demo: its command-line name, its class and how to create it. */
    public static final class Entry {
        private final String name;
        /** The class every demo it creates has: a demo's entry is found without a new one. */
        private final Class<? extends DemoState> type;
        private final Supplier<? extends DemoState> factory;
        /** Creates it with a particle count ({@code --particles}); null if it has none. */
        private final IntFunction<? extends DemoState> countedFactory;

        <D extends DemoState> Entry(String name, Class<D> type, Supplier<D> factory) {
            this(name, type, factory, null);
        }

        <D extends DemoState> Entry(String name, Class<D> type, Supplier<D> factory,
                IntFunction<D> countedFactory) {
            this.name = name;
            this.type = type;
            this.factory = factory;
            this.countedFactory = countedFactory;
        }

        /** @return the name used by {@code particle-lab demo NAME} (not null) */
        public String getName() {
            return name;
        }

        /** @return the class of the demos it creates (not null) */
        public Class<? extends DemoState> getType() {
            return type;
        }

        /** @return a new instance of the demo (not null) */
        public DemoState create() {
            return factory.get();
        }

        /** @return true if the demo takes a particle count ({@code --particles}) */
        public boolean hasParticleCount() {
            return countedFactory != null;
        }

        /**
         * Create the demo with a particle count, if it takes one.
         *
         * @param particles how many particles (in the demo's range; ignored by a demo
         *     without a count)
         * @return a new instance of the demo (not null)
         */
        public DemoState create(int particles) {
            return countedFactory == null ? factory.get() : countedFactory.apply(particles);
        }
    }

    private static final List<Entry> ENTRIES = Collections.unmodifiableList(List.of(
            new Entry("uniform", UniformMotionDemo.class, UniformMotionDemo::new),
            new Entry("pull", GravitationalPullDemo.class, GravitationalPullDemo::new),
            new Entry("drag", DragDemo.class, DragDemo::new),
            new Entry("thrust", ThrustDemo.class, ThrustDemo::new),
            new Entry("aiming", HelloAimingDemo.class, HelloAimingDemo::new),
            new Entry("iterate", IterativeAimingDemo.class, IterativeAimingDemo::new),
            new Entry("cheat", FastBulletsDemo.class, FastBulletsDemo::new),
            new Entry("height", AnyHeightDemo.class, AnyHeightDemo::new),
            new Entry("bounce", BounceDemo.class, BounceDemo::new),
            new Entry("collisions", CollisionsDemo.class, CollisionsDemo::new),
            new Entry("tunnelling", TunnellingDemo.class, TunnellingDemo::new),
            new Entry("targets", TargetsDemo.class, TargetsDemo::new),
            new Entry("rotation", RotationDemo.class, RotationDemo::new),
            new Entry("throw", SpinThrowDemo.class, SpinThrowDemo::new),
            new Entry("racket", TennisRacketDemo.class, TennisRacketDemo::new),
            new Entry("wind", WindDemo.class, WindDemo::new),
            new Entry("fountain", FountainDemo.class, FountainDemo::new, particles -> {
                FountainDemo fountain = new FountainDemo();
                fountain.setParticleCount(particles);
                return fountain;
            }),
            new Entry("spring", SpringDemo.class, SpringDemo::new),
            new Entry("clip", ClipResponseDemo.class, ClipResponseDemo::new)));

    private DemoCatalog() {
    }

    /**
     * Return the demos in lecture order.
     *
     * @return an unmodifiable list (not null)
     */
    public static List<Entry> entries() {
        return ENTRIES;
    }

    /**
     * Return the demos' command-line names in lecture order.
     *
     * @return a new list (not null)
     */
    public static List<String> names() {
        List<String> names = new ArrayList<>();
        for (Entry entry : ENTRIES) {
            names.add(entry.getName());
        }
        return names;
    }

    /**
     * Find a demo's position by its name.
     *
     * @param name the command-line name (case-insensitive), or a 1-based number
     * @return the index (&ge;0), or -1 if there is no such demo
     */
    public static int indexOf(String name) {
        int number = numberOf(name);
        for (int i = 0; i < ENTRIES.size(); ++i) {
            if (number == i + 1 || ENTRIES.get(i).getName().equalsIgnoreCase(name)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Find the catalogue's entry of a demo by its class, creating no demo.
     *
     * @param demo a demo (not null)
     * @return the index (&ge;0), or -1 if no entry creates demos of its class
     */
    public static int indexOfDemo(DemoState demo) {
        for (int i = 0; i < ENTRIES.size(); ++i) {
            if (ENTRIES.get(i).getType() == demo.getClass()) {
                return i;
            }
        }
        return -1;
    }

    /**
     * Read a demo's number as written in its canonical form ("7", not "07" or "+7"), without
     * allocating: a lookup may run every frame (a tour question finds its stop's demo).
     *
     * @param name the text (may be null)
     * @return the number, or -1 if the text is not one
     */
    private static int numberOf(String name) {
        if (name == null || name.isEmpty() || name.length() > 4 || name.charAt(0) == '0') {
            return -1;
        }
        int number = 0;
        for (int i = 0; i < name.length(); ++i) {
            char c = name.charAt(i);
            if (c < '0' || c > '9') {
                return -1;
            }
            number = 10 * number + (c - '0');
        }
        return number;
    }

    /**
     * Create one instance of every demo, in lecture order.
     *
     * @return a new list (not null)
     */
    public static List<DemoState> createAll() {
        List<DemoState> demos = new ArrayList<>();
        for (Entry entry : ENTRIES) {
            demos.add(entry.create());
        }
        return demos;
    }

    /**
     * Create one instance of every demo, in lecture order, those that take a particle count
     * ({@code --particles}) with the one given.
     *
     * @param particles the count (in the range of those demos)
     * @return a new list (not null)
     */
    public static List<DemoState> createAll(int particles) {
        List<DemoState> demos = new ArrayList<>();
        for (Entry entry : ENTRIES) {
            demos.add(entry.create(particles));
        }
        return demos;
    }

    /**
     * Name the demo that takes a particle count, for {@code --particles}' messages.
     *
     * @return its command-line name (not null)
     */
    public static String nameWithParticleCount() {
        for (Entry entry : ENTRIES) {
            if (entry.hasParticleCount()) {
                return entry.getName();
            }
        }
        throw new IllegalStateException("no demo of the catalogue takes a particle count");
    }
}
