package particlelab.lecture;

import particlelab.demo.DemoParameter;
import particlelab.view.TextFormat;
import particlelab.world.SplitMixRandom;

/**
 * A demo's bug hunt: the lecture code's faults that belong to it, as one switch
 * ({@code --set fault=NAME}; {@code none}, the default, runs the lecture's correct code), and
 * "spot the fault" ({@code --set fault=random}, seeded with {@code --set seed=N}): one of the
 * demo's faults picked at random, the HUD and the sphere's label saying only that one is on,
 * until the reveal key names it with its consequence in numbers. The demo owns the physics:
 * it asks {@link #active()} at each launch and moves the coefficients into the fault's force
 * ({@link LectureFaults}); this class only chooses and writes.
 *
 * <p>The pick is {@code floor(n·u)} with u the first double of the project's SplitMix64
 * ({@link SplitMixRandom}, the same as {@code new SplittableRandom(bits).nextDouble()})
 * seeded with the seed's float bits, the value as given (no parameter has a grid), so a seed
 * names the same fault on every machine and at every reset. ({@code java.util.Random}'s
 * first {@code nextInt(2)} is 1 for every seed from 1 to 6: its first draw mixes a small seed
 * too little.) Per frame
 * ({@link #appendHudLine}) it allocates nothing.
 */
final class FaultHunt {

    /** The switch's command-line name. */
    static final String PARAMETER = "fault";
    /** The reveal key's words in the help (one short row: the help stays legible). */
    static final String REVEAL_DESCRIPTION = "bug hunt: reveal the hidden fault";
    /** The seed's command-line name. */
    static final String SEED_PARAMETER = "seed";
    /** The switch's value for the lecture's correct code. */
    static final String NONE = "none";
    /** The switch's value for "spot the fault". */
    static final String RANDOM = "random";
    /** The largest seed offered (whole numbers are exact floats up to 2^24). */
    static final int MAX_SEED = 9999;

    /** The faults' names, as {@code --set fault=} takes them. */
    private final String[] ids;
    /** What each fault is, for the HUD ... */
    private final String[] titles;
    /** ... and in two or three words for the sphere's label, which must stay short. */
    private final String[] labels;
    /** The switch's values: none, the faults, random. */
    private final String[] choices;
    /** The switch as set: 0 none, 1 to n a fault, n + 1 random. */
    private int chosen;
    /** The seed as set (a whole number from the keys; any value in the range as given). */
    private float seed = 1f;
    /** The fault the seed picks (1 to n), drawn when the seed is set, not every frame. */
    private int picked;
    private boolean revealed;

    /**
     * Declare a demo's faults.
     *
     * @param ids the faults' command-line names, e.g. "p-before-v" (at least 1; copied)
     * @param titles what each one is, in a few words, e.g. "P updated before V" (copied)
     * @param labels each one in two or three words for the label, e.g. "P before V" (copied)
     */
    FaultHunt(String[] ids, String[] titles, String[] labels) {
        if (ids.length < 1 || ids.length != titles.length || ids.length != labels.length) {
            throw new IllegalArgumentException("a bug hunt needs at least one fault and a"
                    + " title and a label for each, but had " + ids.length + ", "
                    + titles.length + " and " + labels.length);
        }
        this.ids = ids.clone();
        this.titles = titles.clone();
        this.labels = labels.clone();
        choices = new String[ids.length + 2];
        choices[0] = NONE;
        System.arraycopy(ids, 0, choices, 1, ids.length);
        choices[ids.length + 1] = RANDOM;
        picked = 1 + pick(seed, ids.length);
    }

    /**
     * Declare the switch, {@code --set fault=none|...|random}, applied at the next launch.
     *
     * @param changed run after the switch changed, to move the coefficients (not null)
     * @return the declaration (not null)
     */
    DemoParameter switchParameter(Runnable changed) {
        return DemoParameter.choice(PARAMETER, "lecture-code fault", choices, 0,
                DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    int wanted = Math.round(value);
                    if (wanted != chosen) {
                        chosen = wanted;
                        revealed = false;
                        changed.run();
                    }
                });
    }

    /**
     * Declare the seed of "spot the fault", {@code --set seed=N}.
     *
     * @param changed run after the seed changed (not null)
     * @return the declaration (not null)
     */
    DemoParameter seedParameter(Runnable changed) {
        return new DemoParameter(SEED_PARAMETER, "spot-the-fault seed", "", 1f, MAX_SEED, 1f,
                1f, 0, DemoParameter.Applies.NEXT_LAUNCH, value -> {
                    if (value != seed) {
                        seed = value;
                        picked = 1 + pick(seed, ids.length);
                        revealed = false;
                        changed.run();
                    }
                });
    }

    /**
     * Return the fault that runs: the one set, or the seed's pick in "spot the fault".
     * Allocates nothing.
     *
     * @return 0 for none, else 1 to the number of faults (the order they were declared in)
     */
    int active() {
        return chosen <= ids.length ? chosen : picked;
    }

    /**
     * Return the fault a seed picks among some.
     *
     * @param seed the seed (any float)
     * @param count how many faults (&ge;1)
     * @return 0 to count − 1
     */
    static int pick(float seed, int count) {
        double u = new SplitMixRandom(Float.floatToIntBits(seed)).nextDouble();
        return Math.min(count - 1, (int) (count * u));
    }

    /** @return the seed of "spot the fault", as set */
    float getSeed() {
        return seed;
    }

    /** @return true if the fault that runs is hidden: "spot the fault", not yet revealed */
    boolean isHidden() {
        return chosen == ids.length + 1 && !revealed;
    }

    /** @return true in "spot the fault" mode */
    boolean isSpotting() {
        return chosen == ids.length + 1;
    }

    /** Reveal the hidden fault (the key): from now on the HUD and the label name it. */
    void reveal() {
        revealed = true;
    }

    /**
     * Return a fault's command-line name.
     *
     * @param fault 1 to the number of faults
     * @return e.g. "p-before-v" (not null)
     */
    String id(int fault) {
        return ids[fault - 1];
    }

    /**
     * Return the name of the fault the demo runs now.
     *
     * @return its {@code --set fault=} name, or {@value #NONE}
     */
    String activeName() {
        int fault = active();
        return fault == 0 ? NONE : id(fault);
    }

    /**
     * Write a sphere's label with the fault it runs: as given with none, "[FAULT: label]"
     * when one is on and shown, "[FAULT: ?]" while hidden. Called at a launch or a reveal.
     *
     * @param base the sphere's own label (not null)
     * @return the label (not null)
     */
    String label(String base) {
        int fault = active();
        if (fault == 0) {
            return base;
        }
        return base + "  [FAULT: " + (isHidden() ? "?" : labels[fault - 1]) + "]";
    }

    /**
     * Append the bug hunt's HUD line, if a fault runs: which one (or that one is hidden and
     * how to reveal it) and, shown, its consequence. Allocates nothing.
     *
     * @param text where to append (not null, modified)
     * @param revealKey the reveal key as printed, e.g. "B" (not null)
     * @param consequence the fault's consequence in numbers, one phrase (not null; written
     *     only once the fault is shown)
     */
    void appendHudLine(StringBuilder text, String revealKey, CharSequence consequence) {
        int fault = active();
        if (fault == 0) {
            return;
        }
        if (isHidden()) {
            text.append("SPOT THE FAULT (seed ");
            DemoParameter.appendShort(text, seed, 2).append("): ");
            if (ids.length == 1) {
                text.append("this code has a lecture-code fault");
            } else {
                TextFormat.appendFixed(text.append("one of "), ids.length, 0)
                        .append(" lecture-code faults is on");
            }
            text.append(". Which? ").append(revealKey).append(" reveals it\n");
            return;
        }
        text.append("FAULT on: ").append(titles[fault - 1]).append(" (fault=")
                .append(ids[fault - 1]).append("): ").append(consequence).append('\n');
    }
}
