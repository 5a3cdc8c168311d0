package particlelab.demo;

import particlelab.view.TextFormat;

/**
 * What a demo shows in presentation mode (F8, {@code --present}), beside its title: one or two
 * key formula lines with their live numbers, and the one readout the slide is about, all in
 * large type. A demo fills it in {@link DemoState#writePresentation}, every frame, from its
 * own numbers: append with {@link particlelab.view.TextFormat} and constant strings, into the
 * builders this writer hands out, which are reused, so writing allocates nothing.
 *
 * <pre>{@code
 * protected void writePresentation(Presentation slide) {
 *     TextFormat.appendFixed(slide.formula().append("a = g - (b/m)V,   b/m = "), bm, 2);
 *     slide.readout().append("|V| = ") ...
 * }
 * }</pre>
 */
public final class Presentation {

    /** The most formula lines a slide shows. */
    public static final int MAX_FORMULA_LINES = 2;

    private final StringBuilder formulas = new StringBuilder(256);
    private final StringBuilder readout = new StringBuilder(128);
    private int formulaLines;
    private boolean readoutTaken;

    /**
     * Create an empty slide (by the demo, which fills one every frame).
     */
    Presentation() {
    }

    /**
     * Begin a formula line and return where to write it: append the line, without a line
     * feed. At most {@value #MAX_FORMULA_LINES} per slide.
     *
     * @return the formulas' builder, positioned at the new line (live, append only)
     * @throws IllegalStateException on a third formula line
     */
    public StringBuilder formula() {
        if (formulaLines >= MAX_FORMULA_LINES) {
            throw new IllegalStateException("a slide shows at most " + MAX_FORMULA_LINES
                    + " formula lines");
        }
        if (formulaLines > 0) {
            formulas.append('\n');
        }
        ++formulaLines;
        return formulas;
    }

    /**
     * Return where to write the slide's one readout (one line, no line feed).
     *
     * @return the readout's builder, empty (live, append only)
     * @throws IllegalStateException if the readout was already written on this slide
     */
    public StringBuilder readout() {
        if (readoutTaken) {
            throw new IllegalStateException("a slide has one readout");
        }
        readoutTaken = true;
        return readout;
    }

    /**
     * Return the formula lines as written.
     *
     * @return the lines, separated by line feeds (live, do not modify)
     */
    public CharSequence getFormulas() {
        return formulas;
    }

    /**
     * Return the readout as written.
     *
     * @return the readout, one line (live, do not modify)
     */
    public CharSequence getReadout() {
        return readout;
    }

    /** @return how many formula lines were written (0 to {@value #MAX_FORMULA_LINES}) */
    public int countFormulaLines() {
        return formulaLines;
    }

    /**
     * Append a particle's state as its HUD line shows it on the same frame: its speed while
     * it flies ("11.84 m/s"), where it landed once it has ("x = 9.81 m", the HUD's landing
     * x). Allocates nothing.
     *
     * @param text where to append, e.g. {@link #readout()} (not null, modified)
     * @param particle one of the demo's particles (not null)
     * @return text
     */
    public static StringBuilder appendSpeedOrLanding(StringBuilder text,
            DemoParticle particle) {
        if (particle.hasLanded()) {
            return TextFormat.appendFixed(text.append("x = "), particle.getLandingX(), 2)
                    .append(" m");
        }
        return TextFormat.appendFixed(text, particle.getParticle().velocity.length(), 2)
                .append(" m/s");
    }

    /** Empty the slide, for the next frame's writing. Allocates nothing. */
    void clear() {
        formulas.setLength(0);
        readout.setLength(0);
        formulaLines = 0;
        readoutTaken = false;
    }
}
