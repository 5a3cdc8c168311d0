package particlelab.grading;

import java.util.List;

/** The exercises, in the order of the lecture: an explicit list, no classpath scanning. */
public final class Exercises {

    /** Every exercise; a new one is one more line here (docs/exercises.md). */
    public static final List<Exercise> ALL = List.of(
            RecipeChecks.exercise(),
            QuadraticDragChecks.exercise(),
            AimingChecks.exercise(),
            LaunchAnglesChecks.exercise(),
            ImpulseChecks.exercise(),
            SweptPlaneChecks.exercise(),
            RotationChecks.exercise(),
            OwnDemoChecks.exercise());

    private Exercises() {
    }

    /**
     * The simple name of the class that implements a contract.
     *
     * @param contract an exercise's contract
     * @return the class name shared by the exercise and its solution
     */
    static String classNameOf(Class<?> contract) {
        for (int i = 0; i < ALL.size(); ++i) {
            if (ALL.get(i).contract() == contract) {
                return ALL.get(i).className();
            }
        }
        throw new IllegalArgumentException("no exercise has the contract " + contract.getName());
    }
}
