package particlelab.reference;

/**
 * Checks shared by the stepper constructors.
 */
final class Steppers {

    private Steppers() {
    }

    static ForceModel require(ForceModel forces) {
        if (forces == null) {
            throw new IllegalArgumentException("forces must be a force model, but was null");
        }
        return forces;
    }
}
