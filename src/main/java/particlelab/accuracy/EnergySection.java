package particlelab.accuracy;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import particlelab.files.SafeFiles;
import particlelab.reference.VelocityVerlet;


/**
 * The report's energy section (issue 32): the numerical energy, the energy a stepper itself
 * creates or destroys, against h for the five steppers of the report in three cases
 * (gravity, gravity with linear drag, a spring), with the fitted orders.
 *
 * <p>The numerical energy of a run is {@code max_n |E_h(t_n) − E(t_n)|} over its steps, with
 * {@code E = K + U + spring} of the stepped state and E(t) the exact solution's (constant
 * for gravity and the spring; with drag, the energy the exact path keeps after the drag's
 * loss): the ledger's numerical column measured against the exact physics' work. The
 * steppers are written here plainly for an acceleration of position and velocity,
 * {@code a = g − k·V − ω²·P}, since the spring needs a force of position; per unit mass
 * (m = 1 kg), in double.
 *
 * <p>An energy's order can exceed the trajectory's: on the spring the explicit midpoint
 * step's amplification is {@code |R|² = 1 + (ωh)⁴/4} (order 3 in energy) and RK4's
 * {@code 1 − (ωh)⁶/72} (order 5); under drag, games' Verlet evaluates the drag at V½ and is
 * first order.
 */
public final class EnergySection {

    /** The section's CSV. */
    public static final String CSV = "energy_orders.csv";
    /** Its header. */
    public static final String HEADER = "case,method,h_s,numerical_J";
    /** Every file the section writes. */
    public static final List<String> FILES = Collections.unmodifiableList(Arrays.asList(CSV));
    /** The section's heading in {@code index.md}. */
    public static final String HEADING = "## Energy: the numerical energy of each stepper";

    /** The cases: their names, g down (m/s²), k = b/m (1/s), ω (rad/s), and the start. */
    static final String[] CASES = {"gravity", "drag", "spring"};
    private static final double[] G_DOWN = {9.8, 9.8, 0.0};
    private static final double[] K = {0.0, 0.5, 0.0};
    private static final double[] OMEGA = {0.0, 0.0, 2.0};
    private static final double[][] START = {{0.0, 0.0, 10.0, 10.0}, {0.0, 0.0, 10.0, 10.0},
        {1.0, 0.0, 0.0, 0.0}};
    /** The steppers, in the report's order. */
    static final String[] METHODS = {"forward", "semi-implicit", "verlet", "midpoint", "rk4"};
    /** The steps (s), largest first: 1/15 s halved six times. */
    static final double[] STEPS = {1.0 / 15, 1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240,
        1.0 / 480, 1.0 / 960};
    /** How long each run is (s). */
    static final double DURATION_SECONDS = 2.0;
    /** Below this (J) an error is double round-off: the method is exact for the case. */
    static final double ROUND_OFF_JOULES = 1e-9;

    private EnergySection() {
    }

    /**
     * Measure the section and write it: {@value #CSV} and the section of {@code index.md}.
     *
     * @param folder the report's folder, where {@code index.md} already is (not null)
     * @throws IOException if a file cannot be written
     */
    public static void write(Path folder) throws IOException {
        double[][][] errors = measure();
        SafeFiles.write(folder.resolve(CSV), csv(errors), false);
        SafeFiles.append(folder.resolve("index.md"), markdown(errors));
    }

    /**
     * Measure every case, method and step.
     *
     * @return the numerical energy (J), indexed [case][method][step]
     */
    static double[][][] measure() {
        double[][][] errors = new double[CASES.length][METHODS.length][STEPS.length];
        for (int c = 0; c < CASES.length; ++c) {
            for (int m = 0; m < METHODS.length; ++m) {
                for (int s = 0; s < STEPS.length; ++s) {
                    errors[c][m][s] = numericalEnergy(c, m, STEPS[s]);
                }
            }
        }
        return errors;
    }

    /**
     * Fit the order of one case and method: the slope of log(error) against log(h).
     *
     * @param errors one case's and method's errors, in {@link #STEPS}' order
     * @return the order, or NaN if the method is exact for the case (round-off) or fewer
     *     than {@link OrderFit#MIN_POINTS} points stand clear of round-off
     */
    static double order(double[] errors) {
        return OrderFit.slope(STEPS, errors, ROUND_OFF_JOULES);
    }

    /** The largest |E_h − E_exact| over a run of one case, method and h (J, m = 1 kg). */
    static double numericalEnergy(int c, int method, double h) {
        double[] s = START[c].clone();
        int steps = (int) Math.round(DURATION_SECONDS / h);
        double worst = 0.0;
        double[] exact = new double[4];
        for (int n = 1; n <= steps; ++n) {
            step(c, method, s, h);
            exactState(c, n * h, exact);
            worst = Math.max(worst, Math.abs(energy(c, s) - energy(c, exact)));
        }
        return worst;
    }

    /** E = ½|V|² + g·y + ½ω²|P|² per kilogram, state {x, y, vx, vy}. */
    static double energy(int c, double[] s) {
        double w = OMEGA[c];
        return 0.5 * (s[2] * s[2] + s[3] * s[3]) + G_DOWN[c] * s[1]
                + 0.5 * w * w * (s[0] * s[0] + s[1] * s[1]);
    }

    /** The exact state at time t (NUMERICS' exact updates; the spring's cosine). */
    static void exactState(int c, double t, double[] store) {
        double[] s0 = START[c];
        double g = G_DOWN[c];
        if (OMEGA[c] > 0.0) {
            double w = OMEGA[c];
            for (int i = 0; i < 2; ++i) {
                store[i] = s0[i] * Math.cos(w * t) + s0[2 + i] / w * Math.sin(w * t);
                store[2 + i] = -s0[i] * w * Math.sin(w * t) + s0[2 + i] * Math.cos(w * t);
            }
        } else if (K[c] > 0.0) {
            double z = K[c] * t;
            double phi1 = -Math.expm1(-z) / z;
            double phi2 = (z - 1.0 + Math.exp(-z)) / (z * z);
            double[] ga = {0.0, -g};
            for (int i = 0; i < 2; ++i) {
                store[2 + i] = Math.exp(-z) * s0[2 + i] + t * phi1 * ga[i];
                store[i] = s0[i] + t * phi1 * s0[2 + i] + t * t * phi2 * ga[i];
            }
        } else {
            store[0] = s0[0] + t * s0[2];
            store[1] = s0[1] + t * s0[3] - 0.5 * g * t * t;
            store[2] = s0[2];
            store[3] = s0[3] - g * t;
        }
    }

    /** a = g − k·V − ω²·P, one component. */
    private static double acceleration(int c, int axis, double position, double velocity) {
        double w = OMEGA[c];
        return (axis == 1 ? -G_DOWN[c] : 0.0) - K[c] * velocity - w * w * position;
    }

    /** One step of a method, in place, state {x, y, vx, vy}; the axes are independent. */
    static void step(int c, int method, double[] s, double h) {
        for (int i = 0; i < 2; ++i) {
            double p = s[i];
            double v = s[2 + i];
            switch (method) {
                case 0: { // forward Euler: P with the old V
                    double a = acceleration(c, i, p, v);
                    s[i] = p + h * v;
                    s[2 + i] = v + h * a;
                    break;
                }
                case 1: { // the lecture's step: V first, then P with the new V
                    double vNew = v + h * acceleration(c, i, p, v);
                    s[2 + i] = vNew;
                    s[i] = p + h * vNew;
                    break;
                }
                case 2: { // velocity Verlet as games write it (the report's VelocityVerlet)
                    double half = v + 0.5 * h * acceleration(c, i, p, v);
                    double pNew = p + h * half;
                    s[i] = pNew;
                    s[2 + i] = half + 0.5 * h * acceleration(c, i, pNew, half);
                    break;
                }
                case 3: { // explicit midpoint: the slope half a step ahead
                    double vm = v + 0.5 * h * acceleration(c, i, p, v);
                    double pm = p + 0.5 * h * v;
                    s[i] = p + h * vm;
                    s[2 + i] = v + h * acceleration(c, i, pm, vm);
                    break;
                }
                default: { // classic Runge–Kutta 4
                    double k1p = v;
                    double k1v = acceleration(c, i, p, v);
                    double k2p = v + 0.5 * h * k1v;
                    double k2v = acceleration(c, i, p + 0.5 * h * k1p, k2p);
                    double k3p = v + 0.5 * h * k2v;
                    double k3v = acceleration(c, i, p + 0.5 * h * k2p, k3p);
                    double k4p = v + h * k3v;
                    double k4v = acceleration(c, i, p + h * k3p, k4p);
                    s[i] = p + h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
                    s[2 + i] = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
                    break;
                }
            }
        }
    }

    /** The text of {@value #CSV}. */
    static String csv(double[][][] errors) {
        StringBuilder text = new StringBuilder(HEADER).append('\n');
        for (int c = 0; c < CASES.length; ++c) {
            for (int m = 0; m < METHODS.length; ++m) {
                for (int s = 0; s < STEPS.length; ++s) {
                    text.append(CASES[c]).append(',').append(METHODS[m]).append(',')
                            .append(STEPS[s]).append(',').append(errors[c][m][s])
                            .append('\n');
                }
            }
        }
        return text.toString();
    }

    /** The section of {@code index.md}: the orders, and the numerical energy at 1/60 s. */
    static String markdown(double[][][] errors) {
        StringBuilder text = new StringBuilder("\n").append(HEADING).append("\n\n");
        text.append("The energy each stepper creates or destroys by itself, "
                + "`max_n |E_h(t_n) − E(t_n)|` over 2 s with m = 1 kg, E = K + U + spring and "
                + "E(t) the exact solution's: gravity from (0, 0) at (10, 10) m/s, the same "
                + "with linear drag b/m = 0.5 /s, a spring with ω = 2 rad/s from x = 1 m at "
                + "rest. Fitted order (slope of log error against log h, h = 1/15 s to "
                + "1/960 s, `" + CSV + "`), and the numerical energy at h = 1/60 s; "
                + "\"exact\" where the error is round-off.\n\n");
        text.append("| method |");
        for (String name : CASES) {
            text.append(' ').append(name).append(": order | at 1/60 s (J) |");
        }
        text.append("\n|---|");
        for (int c = 0; c < CASES.length; ++c) {
            text.append("---|---|");
        }
        text.append('\n');
        int sixtieth = 2;
        for (int m = 0; m < METHODS.length; ++m) {
            text.append("| ").append(METHODS[m]).append(" |");
            for (int c = 0; c < CASES.length; ++c) {
                double p = order(errors[c][m]);
                double at = errors[c][m][sixtieth];
                text.append(' ').append(at <= ROUND_OFF_JOULES ? "exact"
                        : Double.isNaN(p) ? "-" : String.format(Locale.ROOT, "%.2f", p))
                        .append(" | ").append(String.format(Locale.ROOT, "%.3g", at))
                        .append(" |");
            }
            text.append('\n');
        }
        return text.toString();
    }
}
