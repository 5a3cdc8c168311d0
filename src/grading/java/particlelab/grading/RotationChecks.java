package particlelab.grading;

import static particlelab.grading.Numbers.f;

import com.jme3.math.FastMath;
import com.jme3.math.Matrix3f;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import java.util.List;
import particlelab.coursework.RotationExercise;

/** Exercise 7's checks: one matrix Euler step, and the cure keeping R a rotation. */
final class RotationChecks {

    private static final float H = 1f / 60f;

    private RotationChecks() {
    }

    static Exercise exercise() {
        return new Exercise(7, "Rotation", RotationExercise.class, "Rotation",
                List.of(new Check("euler step", RotationChecks::stepAddsHOmegaTildeR),
                        new Check("drift cured", RotationChecks::staysARotationForASecond),
                        new Check("keeps R", RotationChecks::cureMovesRLittle)));
    }

    /** A turned R (about (1, 2, 3) by 0.7 rad), one step: {@code R + h·ω̃·R} in double. */
    private static void stepAddsHOmegaTildeR(Submission s) throws Exception {
        Matrix3f r = turned();
        Vector3f w = new Vector3f(0.5f, -1f, 2f);
        float h = 0.01f;
        double[][] expected = new double[3][3];
        double[][] withoutR = new double[3][3];
        double[][] tilde = {{0, -w.z, w.y}, {w.z, 0, -w.x}, {-w.y, w.x, 0}};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                double sum = 0;
                for (int k = 0; k < 3; ++k) {
                    sum += tilde[i][k] * r.get(k, j);
                }
                expected[i][j] = r.get(i, j) + h * sum;
                withoutR[i][j] = r.get(i, j) + h * tilde[i][j];
            }
        }
        s.create(RotationExercise.class).step(r, w, h);
        // Entries under 1 plus 0.03: two float roundings each, under 1e-6.
        if (within(expected, r, 1e-6)) {
            return;
        }
        if (within(withoutR, r, 1e-6)) {
            throw new Mistake("you added h·ω̃ without R: the step is R += h·ω̃·R (ω × each"
                    + " column of R)");
        }
        throw new Mistake("after one step R[0][0] = " + f(r.get(0, 0)) + ", R + h ω̃ R gives "
                + f(expected[0][0]) + ": column j of ω̃ R is ω × (column j of R)");
    }

    /** One second at 1 rev/s, h = 1/60, step then cure: RᵀR = I and det R = 1. */
    private static void staysARotationForASecond(Submission s) throws Exception {
        RotationExercise rotation = s.create(RotationExercise.class);
        Matrix3f r = new Matrix3f();
        Vector3f w = new Vector3f(1f, 1f, 1f).normalizeLocal().multLocal(FastMath.TWO_PI);
        for (int n = 0; n < 60; ++n) {
            rotation.step(r, w, H);
            rotation.orthonormalize(r);
        }
        // Float rotations renormalised every step: RᵀR within a few ulp of I (1e-5 is loose);
        // uncured, det R would be 1.924 after this second (docs/numerics.md).
        double error = orthonormalityError(r);
        if (!(error <= 1e-5) || !(Math.abs(r.determinant() - 1f) <= 1e-5f)) {
            throw new Mistake("after 60 steps and cures R^T R is off I by " + f(error)
                    + " and det R = " + f(r.determinant()) + ": orthonormalize must make R a"
                    + " rotation again (Gram-Schmidt or polar)");
        }
    }

    /** The cure of a slightly grown R moves it by about the growth, not to some other R. */
    private static void cureMovesRLittle(Submission s) throws Exception {
        Matrix3f r = turned();
        Matrix3f grown = new Matrix3f(r).multLocal(1.001f);
        grown.set(0, 1, grown.get(0, 1) + 0.001f);
        s.create(RotationExercise.class).orthonormalize(grown);
        double[][] expected = new double[3][3];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                expected[i][j] = r.get(i, j);
            }
        }
        // Perturbations of 1e-3: the cured matrix is within a few 1e-3 of R.
        if (!within(expected, grown, 5e-3) || !(orthonormalityError(grown) <= 1e-5)) {
            throw new Mistake("orthonormalize moved R (grown by 0.1 %) to R[0][0] = "
                    + f(grown.get(0, 0)) + " from " + f(r.get(0, 0))
                    + ": cure the drift, keep the orientation");
        }
    }

    private static Matrix3f turned() {
        Vector3f axis = new Vector3f(1f, 2f, 3f).normalizeLocal();
        return new Quaternion().fromAngleNormalAxis(0.7f, axis).toRotationMatrix();
    }

    private static boolean within(double[][] expected, Matrix3f actual, double tolerance) {
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                if (!Numbers.near(expected[i][j], actual.get(i, j), tolerance)) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The largest entry of {@code RᵀR − I}, or NaN. */
    private static double orthonormalityError(Matrix3f r) {
        double worst = 0;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                double dot = 0;
                for (int k = 0; k < 3; ++k) {
                    dot += (double) r.get(k, i) * r.get(k, j);
                }
                double error = Math.abs(dot - (i == j ? 1 : 0));
                if (!(error <= worst)) {
                    worst = error;
                }
            }
        }
        return worst;
    }
}
