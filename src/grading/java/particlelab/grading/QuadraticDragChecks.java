package particlelab.grading;

import static particlelab.grading.Numbers.f;
import static particlelab.grading.Numbers.v;

import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.coursework.QuadraticDragExercise;

/** Exercise 2's checks: the force's direction, and its magnitude c·|V|². */
final class QuadraticDragChecks {

    private static final float C = 0.1f;

    private QuadraticDragChecks() {
    }

    static Exercise exercise() {
        return new Exercise(2, "QuadraticDrag", QuadraticDragExercise.class, "Quadratic drag",
                List.of(new Check("direction", QuadraticDragChecks::opposesTheMotion),
                        new Check("magnitude", QuadraticDragChecks::growsWithTheSquare)));
    }

    /** Against V, added to the net force, zero (and finite) at rest. */
    private static void opposesTheMotion(Submission s) throws Exception {
        QuadraticDragExercise drag = s.create(QuadraticDragExercise.class);
        Vector3f velocity = new Vector3f(3f, -4f, 12f);
        Vector3f before = new Vector3f(1f, 2f, 3f);
        Vector3f net = new Vector3f(before);
        drag.addForce(velocity, C, net);
        Numbers.requireFinite(net, "the net force");
        Vector3f added = net.subtract(before);
        // Parallel to V: |F × V| is rounding only (|F|·|V| ≈ 220, float: under 1e-3).
        if (added.dot(velocity) >= 0f || added.cross(velocity).length() > 1e-3f) {
            throw new Mistake("the force added for V = " + v(velocity) + " is " + v(added)
                    + ": drag points against V, along -V, and is added to netForce");
        }
        Vector3f rest = new Vector3f(1f, 2f, 3f);
        drag.addForce(new Vector3f(), C, rest);
        if (rest.x != 1f || rest.y != 2f || rest.z != 3f) {
            throw new Mistake("at rest the net force became " + v(rest)
                    + ": the drag is 0 at V = 0 (don't divide by |V|)");
        }
    }

    /** {@code |F| = c·|V|²} at two speeds: doubling V quadruples the drag. */
    private static void growsWithTheSquare(Submission s) throws Exception {
        QuadraticDragExercise drag = s.create(QuadraticDragExercise.class);
        float[] speeds = {5f, 10f};
        for (float speed : speeds) {
            Vector3f velocity = new Vector3f(0.6f * speed, 0.8f * speed, 0f);
            Vector3f force = new Vector3f();
            drag.addForce(velocity, C, force);
            double magnitude = force.length();
            double expected = C * speed * speed;
            // A few float roundings of numbers near 10: relative 1e-5 is generous.
            if (Math.abs(magnitude - expected) <= 1e-5 * expected) {
                continue;
            }
            if (Math.abs(magnitude - expected * speed) <= 1e-5 * expected * speed) {
                throw new Mistake("|F| grows with |V|^3: you wrote the slide's -c|V|^2 V;"
                        + " air's drag is -c|V| V, of magnitude c|V|^2");
            }
            throw new Mistake("|F| = " + f(magnitude) + " N at |V| = " + f(speed)
                    + " m/s with c = 0.1; c|V|^2 is " + f(expected));
        }
    }
}
