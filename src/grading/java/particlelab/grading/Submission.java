package particlelab.grading;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The classes graded: by default each exercise's class from one package
 * ({@code particlelab.exercises} or {@code particlelab.solutions}), a fresh instance per use;
 * a test may put another implementation (a mutant) in place of one of them.
 */
public final class Submission {

    private final String packageName;
    private final Map<Class<?>, Supplier<?>> replaced = new HashMap<>();

    /**
     * The classes of one package.
     *
     * @param packageName the package, e.g. {@code particlelab.exercises}
     */
    public Submission(String packageName) {
        this.packageName = packageName;
    }

    /**
     * Puts another implementation in place of one exercise's class.
     *
     * @param <T> the contract
     * @param contract the exercise's contract
     * @param implementation makes a fresh instance
     * @return this submission
     */
    public <T> Submission replace(Class<T> contract, Supplier<? extends T> implementation) {
        replaced.put(contract, implementation);
        return this;
    }

    /**
     * Access the package graded.
     *
     * @return its name
     */
    public String getPackageName() {
        return packageName;
    }

    /**
     * A fresh instance of the class that implements a contract.
     *
     * @param <T> the contract
     * @param contract the contract
     * @return a new instance
     * @throws Exception when the class is missing or cannot be made
     */
    public <T> T create(Class<T> contract) throws Exception {
        Supplier<?> replacement = replaced.get(contract);
        if (replacement != null) {
            return contract.cast(replacement.get());
        }
        String name = packageName + "." + Exercises.classNameOf(contract);
        Class<?> type;
        try {
            type = Class.forName(name);
        } catch (ClassNotFoundException e) {
            throw new Mistake("no class " + name + " (is the exercise's file in place?)");
        }
        return contract.cast(type.getDeclaredConstructor().newInstance());
    }
}
