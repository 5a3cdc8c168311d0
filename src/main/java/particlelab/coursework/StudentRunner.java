package particlelab.coursework;

import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.locks.LockSupport;

/**
 * Runs a student's exercise class inside the app, where nothing it does may take the window
 * down: every call (the constructor too) runs on a daemon worker thread while the caller
 * waits up to a time limit. A call that throws, or has not returned within the limit, turns
 * into one line ({@link #getProblem()}); a call past the limit is abandoned, its thread left
 * behind, and the runner makes no call any more.
 *
 * <p>The class is found by name ({@link #className}), never named in the app's code: the
 * app does not depend on the exercises' source set. {@code gradle run} puts the exercises'
 * classes on the classpath ({@code -Psolutions}: the reference solutions', and the package
 * with them, {@value #PACKAGE_PROPERTY}); the installed app has neither, and says so.
 *
 * <p>A call that returns hands its result back without allocating: the caller's inputs and
 * the worker's outputs cross through plain fields ordered by two volatile counters, the
 * threads wake each other with {@link LockSupport}, and the call itself is a {@link Runnable}
 * the caller made once. Only a failure builds its line.
 */
public final class StudentRunner {

    /** The system property naming the package of the classes run (set by gradle run). */
    public static final String PACKAGE_PROPERTY = "particlelab.exercises.package";
    /** The package when the property is not set: the stubs a student edits. */
    public static final String DEFAULT_PACKAGE = "particlelab.exercises";
    /** What a stub's method throws (an UnsupportedOperationException), shown as it is. */
    public static final String NOT_WRITTEN = "not written yet";
    /** How long one call may take by default before it is abandoned (ns): 1 s. */
    public static final long DEFAULT_LIMIT_NANOS = 1_000_000_000L;
    /** The caller spins this long before it parks (ns): a recipe's step takes far less. */
    private static final long SPIN_NANOS = 20_000L;
    /** The longest single park of the caller (ns); the worker's unpark ends it earlier. */
    private static final long PARK_NANOS = 10_000_000L;
    private static final double NANOS_PER_SECOND = 1e9;

    private final String className;
    private final long limitNanos;
    private Thread worker;
    /** The thread waiting for the call (written before {@link #requested}). */
    private Thread caller;
    /** The call to make (written before {@link #requested}). */
    private Runnable task;
    /** What the last call threw, or null (written before {@link #completed}). */
    private Throwable thrown;
    /** The number of calls asked for and finished: each write publishes the fields above. */
    private volatile long requested;
    private volatile long completed;
    private boolean abandoned;
    private String problem;
    /** The instance {@link #create} made on the worker. */
    private Object created;

    /**
     * Create a runner for one class; no thread starts before the first call.
     *
     * @param className the class's binary name, e.g. {@code particlelab.exercises.Recipe}
     *     (not null)
     * @param limitNanos how long one call may take before it is abandoned (in ns, &gt;0)
     */
    public StudentRunner(String className, long limitNanos) {
        if (className == null || className.isEmpty()) {
            throw new IllegalArgumentException("the student's class name must not be empty,"
                    + " but was " + (className == null ? "null" : "\"\""));
        }
        if (limitNanos <= 0L) {
            throw new IllegalArgumentException("the time limit of a call (ns) must be > 0,"
                    + " but was " + limitNanos);
        }
        this.className = className;
        this.limitNanos = limitNanos;
    }

    /**
     * Name an exercise's class in the package the app was started with: {@value
     * #PACKAGE_PROPERTY}, or else {@value #DEFAULT_PACKAGE}.
     *
     * @param simpleName the exercise's class, e.g. {@code Recipe} (not null)
     * @return the binary name, e.g. {@code particlelab.exercises.Recipe}
     */
    public static String className(String simpleName) {
        return System.getProperty(PACKAGE_PROPERTY, DEFAULT_PACKAGE) + "." + simpleName;
    }

    /**
     * Return the class this runner runs.
     *
     * @return its binary name (not null)
     */
    public String getClassName() {
        return className;
    }

    /**
     * Return how long one call may take.
     *
     * @return the limit (in seconds)
     */
    public double getLimitSeconds() {
        return limitNanos / NANOS_PER_SECOND;
    }

    /**
     * Make an instance of the class, on the worker (its constructor is student code too).
     *
     * @param <T> the exercise's contract
     * @param contract the interface the class must implement (not null)
     * @return the instance, or null when the class is absent, is not a {@code contract},
     *     throws or does not return ({@link #getProblem()} says which)
     */
    public <T> T create(Class<T> contract) {
        Class<?> type;
        try {
            type = Class.forName(className, false, StudentRunner.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            problem = "no class " + className + " here: run it with gradle run"
                    + " (docs/exercises.md)";
            return null;
        }
        if (!contract.isAssignableFrom(type)) {
            problem = className + " does not implement " + contract.getSimpleName();
            return null;
        }
        created = null;
        if (!run(() -> created = newInstance(type))) {
            return null;
        }
        return contract.cast(created);
    }

    /**
     * Make one call on the worker and wait for it, up to the limit. Allocates nothing when
     * the call returns; the call's own allocation happens on the worker's thread.
     *
     * @param call what to run (not null; make it once and reuse it)
     * @return true if it returned; false if it threw, did not return within the limit or the
     *     runner had given up before ({@link #getProblem()} says which)
     */
    public boolean run(Runnable call) {
        if (abandoned) {
            return false;
        }
        if (worker == null) {
            startWorker();
        }
        caller = Thread.currentThread();
        task = call;
        long request = requested + 1L;
        requested = request;
        LockSupport.unpark(worker);
        long start = System.nanoTime();
        while (completed != request) {
            long waited = System.nanoTime() - start;
            if (waited >= limitNanos) {
                abandoned = true;
                problem = "did not return within " + getLimitSeconds()
                        + " s: an endless loop? (no more calls)";
                return false;
            }
            if (waited < SPIN_NANOS) {
                Thread.onSpinWait();
            } else {
                LockSupport.parkNanos(this, Math.min(PARK_NANOS, limitNanos - waited));
            }
        }
        Throwable failure = thrown;
        if (failure != null) {
            thrown = null;
            problem = describe(failure);
            return false;
        }
        return true;
    }

    /**
     * Return what went wrong last, in one line: {@value #NOT_WRITTEN}; "threw" with the
     * exception, its message and the line of the student's file that threw it; "did not
     * return"; or the class is missing.
     *
     * @return the line, or null while every call returned
     */
    public String getProblem() {
        return problem;
    }

    /**
     * Tell whether a call ran past the limit: the runner then calls nothing any more.
     *
     * @return true once abandoned
     */
    public boolean isAbandoned() {
        return abandoned;
    }

    /**
     * Forget a call's failure, to call again (a new launch), unless a call was abandoned.
     */
    public void clearProblem() {
        if (!abandoned) {
            problem = null;
        }
    }

    private void startWorker() {
        worker = new Thread(this::work, "student code " + className);
        // A call that never returns must not keep the app from exiting.
        worker.setDaemon(true);
        worker.start();
    }

    /** The worker: wait for a call, make it, publish what it threw, wake the caller. */
    private void work() {
        long done = 0L;
        while (true) {
            long request = requested;
            if (request == done) {
                LockSupport.park(this);
                continue;
            }
            Throwable failure = null;
            try {
                task.run();
            } catch (Throwable e) {
                // anything the student's code throws is reported, nothing is rethrown
                failure = e;
            }
            thrown = failure;
            done = request;
            completed = request;
            LockSupport.unpark(caller);
        }
    }

    private static Object newInstance(Class<?> type) {
        try {
            return type.getDeclaredConstructor().newInstance();
        } catch (InvocationTargetException e) {
            throw sneaky(e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot make a " + type.getSimpleName()
                    + ": it needs a public constructor without parameters", e);
        }
    }

    /** Rethrow a constructor's own exception unwrapped, for {@link #describe}. */
    @SuppressWarnings("unchecked")
    private static <E extends Throwable> RuntimeException sneaky(Throwable e) throws E {
        throw (E) e;
    }

    /** "threw X: message (File.java:line)", the line the student's class's first frame. */
    private String describe(Throwable e) {
        Throwable cause = e;
        while ((cause instanceof ExceptionInInitializerError
                || cause instanceof ReflectiveOperationException) && cause.getCause() != null) {
            cause = cause.getCause();
        }
        if (cause instanceof UnsupportedOperationException
                && NOT_WRITTEN.equals(cause.getMessage())) {
            return NOT_WRITTEN;
        }
        StringBuilder line = new StringBuilder("threw ").append(cause.getClass().getSimpleName());
        if (cause.getMessage() != null) {
            // one line: a message of several is cut at its first line break
            String message = cause.getMessage();
            int end = message.indexOf('\n');
            line.append(": ").append(end < 0 ? message : message.substring(0, end));
        }
        String nested = className + "$";
        for (StackTraceElement frame : cause.getStackTrace()) {
            if (frame.getClassName().equals(className)
                    || frame.getClassName().startsWith(nested)) {
                line.append(" (").append(frame.getFileName()).append(':')
                        .append(frame.getLineNumber()).append(')');
                break;
            }
        }
        return line.toString();
    }
}
