package particlelab.accuracy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The A/A-controlled verdict of a side-by-side speed comparison. */
class AaControlTest {

    /** Identical code timed in two class loaders, as one A/A pass measured it (issue 35). */
    private static final double[] IDENTICAL_CODE = {0.731, 0.735, 0.733, 0.740, 0.729};

    @Test
    void anAaRunJudgedByItsOwnBandGivesNoVerdict() {
        // An A/A pass used as the A/B row: its median lies inside its own [min, max] band.
        assertEquals(AaControl.NO_VERDICT, AaControl.verdict(IDENTICAL_CODE, IDENTICAL_CODE));
        double[] single = {1.37};
        assertEquals(AaControl.NO_VERDICT, AaControl.verdict(single, single));
    }

    @Test
    void aTightSpreadFarFromOneIsNoVerdictWhenTheAaBandHoldsIt() {
        // Without the control these rounds (0.72 to 0.75, a 4 % spread) would read "B is 27 %
        // faster"; the A/A pass of the same row measured the same 0.73, so they say nothing.
        double[] ab = {0.728, 0.734, 0.738, 0.731, 0.736};
        assertEquals(AaControl.NO_VERDICT, AaControl.verdict(IDENTICAL_CODE, ab));
    }

    @Test
    void identicalCodeHasNoDirection() {
        // The band holds each A/A round's reciprocal too: 0.73 for A′ ÷ A is 1.37 for A ÷ A′,
        // so a B that reads 1.30 against the same A is within what identical code showed.
        assertEquals(AaControl.NO_VERDICT,
                AaControl.verdict(IDENTICAL_CODE, new double[] {1.28, 1.30, 1.33}));
    }

    @Test
    void aMedianOutsideTheBandIsJudgedWithItsDirection() {
        double[] aa = {0.97, 1.02, 0.99, 1.04, 1.00};
        double[] slower = {1.18, 1.25, 1.21, 1.30, 1.19};
        double[] faster = {0.80, 0.82, 0.79, 0.85, 0.81};
        String late = AaControl.verdict(aa, slower);
        String early = AaControl.verdict(aa, faster);
        // Band: 0.97 and 1/0.97 = 1.031 against 1.04 and 1/1.04 = 0.962: [0.962, 1.040].
        assertTrue(late.startsWith("slower (1.210× outside the A/A band 0.962–1.040"), late);
        assertTrue(early.startsWith("faster (0.810×"), early);
    }

    @Test
    void theBandsEdgesCountAsInside() {
        double[] aa = {0.8, 1.25};
        assertEquals(AaControl.NO_VERDICT, AaControl.verdict(aa, new double[] {1.25}));
        assertEquals(AaControl.NO_VERDICT, AaControl.verdict(aa, new double[] {0.8}));
        assertTrue(AaControl.verdict(aa, new double[] {Math.nextUp(1.25)}).startsWith("slower"));
        assertTrue(AaControl.verdict(aa, new double[] {Math.nextDown(0.8)}).startsWith("faster"));
    }

    @Test
    void missingOrNonPositiveRatiosAreNotMeasured() {
        double[] good = {1.0, 1.1};
        assertEquals("not measured", AaControl.verdict(new double[0], good));
        assertEquals("not measured", AaControl.verdict(good, new double[] {Double.NaN}));
        assertEquals("not measured", AaControl.verdict(good, new double[] {0.0}));
        assertEquals("not measured",
                AaControl.verdict(new double[] {Double.POSITIVE_INFINITY}, good));
    }

    @Test
    void medianOfAnEvenCountIsTheMeanOfTheMiddleTwo() {
        assertEquals(2.5, AaControl.median(new double[] {4, 1, 3, 2}), 0.0);
        assertEquals(3.0, AaControl.median(new double[] {5, 3, 1}), 0.0);
    }
}
