package particlelab.view;

/**
 * The sounds a scene can make, one short WAV file each in the top-level {@code assets/Sounds}
 * folder, synthesised by {@link SoundGenerator} (nothing recorded or downloaded).
 */
public enum SoundCue {
    /** A contact faster than the hit threshold: a short damped "tok" (80 ms). */
    IMPACT("impact", 0.080),
    /** A body destroyed in the epilogue: a noise burst whose pitch falls (300 ms). */
    DESTROY("destroy", 0.300);

    private final String label;
    private final String fileName;
    private final String assetPath;
    private final double durationSeconds;

    SoundCue(String label, double durationSeconds) {
        this.label = label;
        this.fileName = label + ".wav";
        this.assetPath = "Sounds/" + fileName;
        this.durationSeconds = durationSeconds;
    }

    /**
     * Return the short name shown on the HUD and used for the file name.
     *
     * @return the name, e.g. "impact" (not null)
     */
    public String getLabel() {
        return label;
    }

    /**
     * Return the file's name in {@code assets/Sounds}.
     *
     * @return e.g. "impact.wav" (not null)
     */
    public String getFileName() {
        return fileName;
    }

    /**
     * Return the path jME's asset manager loads, relative to the {@code assets} folder (which
     * the build puts on the classpath).
     *
     * @return e.g. "Sounds/impact.wav" (not null)
     */
    public String getAssetPath() {
        return assetPath;
    }

    /**
     * Return the sound's length.
     *
     * @return the duration (in seconds, &gt;0)
     */
    public double getDurationSeconds() {
        return durationSeconds;
    }
}
