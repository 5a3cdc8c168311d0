package particlelab.grading;

import java.util.List;

/**
 * One exercise: the class a student writes, the slide it comes from and its checks.
 *
 * @param number the exercise's number (from 1)
 * @param className the class's simple name, the same in the exercises and the solutions
 * @param contract the interface (or base class) the class implements
 * @param slide the lecture slide the exercise comes from
 * @param checks the exercise's tests, one point each
 */
public record Exercise(int number, String className, Class<?> contract, String slide,
        List<Check> checks) {
}
