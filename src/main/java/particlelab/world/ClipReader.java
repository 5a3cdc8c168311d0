package particlelab.world;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * Reads a {@link Clip} from its text form, one keyframe a line:
 * <pre>
 *   # a comment; blank lines are skipped
 *   # t (s)  track   x      y      z   (m, from where the body was at the contact)
 *   0.00     rocket  0      0      0
 *   0.20     rocket  -0.50  0.30   0
 * </pre>
 * A track's keys come in increasing time, the first at {@code t = 0} with offset 0, at least
 * two of them; the tracks' lines may interleave. A bad file is refused with an
 * {@link IllegalArgumentException} naming the file, the line and the bad value.
 */
public final class ClipReader {

    /** The fields of a key line: t, track, x, y, z. */
    private static final int FIELDS = 5;
    /** The latest key time accepted (in seconds, whole): a clip plays a few seconds. */
    private static final float MAX_SECONDS = 60f;
    /** The largest offset accepted (in metres, whole): a clip stays in its scene. */
    private static final float MAX_OFFSET_METRES = 1000f;
    /** The axes' names, for the messages. */
    private static final String[] AXES = {"x", "y", "z"};

    private ClipReader() {
    }

    /**
     * Read a clip from the class path (the {@code assets} folder), e.g.
     * {@code "clips/topple.clip"}.
     *
     * @param resource the resource's path (not null)
     * @return a new clip named by the resource's file name (not null)
     * @throws IllegalArgumentException if there is no such resource or it is not a clip
     */
    public static Clip readResource(String resource) {
        String name = resource.substring(resource.lastIndexOf('/') + 1);
        try (InputStream in = ClipReader.class.getClassLoader().getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalArgumentException("clip " + resource
                        + " is not on the class path (expected in assets/" + resource + ")");
            }
            return read(name, new InputStreamReader(in, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("clip " + resource + " could not be read", e);
        }
    }

    /**
     * Read a clip from text.
     *
     * @param name the clip's name for it and its messages, e.g. a file name (not null)
     * @param text the clip's lines (not null)
     * @return a new clip (not null)
     * @throws IllegalArgumentException naming the line and value if the text is not a clip
     */
    public static Clip parse(String name, String text) {
        try {
            return read(name, new StringReader(text));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Clip read(String name, Reader source) throws IOException {
        List<String> tracks = new ArrayList<>();
        List<List<float[]>> keys = new ArrayList<>();
        BufferedReader lines = new BufferedReader(source);
        int lineNumber = 0;
        for (String line = lines.readLine(); line != null; line = lines.readLine()) {
            ++lineNumber;
            String content = line.trim();
            if (content.isEmpty() || content.startsWith("#")) {
                continue;
            }
            String[] fields = content.split("\\s+");
            String where = "clip " + name + ", line " + lineNumber + ": ";
            if (fields.length != FIELDS) {
                throw new IllegalArgumentException(where + "expected 5 fields (t track x y z),"
                        + " but found " + fields.length + " in '" + content + "'");
            }
            String track = fields[1];
            if (!track.matches("[a-z][a-z0-9_-]*")) {
                throw new IllegalArgumentException(where + "track name '" + track
                        + "' must be a lower-case letter, then letters, digits, '-' or '_'");
            }
            float t = number(where, "time t", fields[0], 0f, MAX_SECONDS, "s");
            float[] key = {t, 0f, 0f, 0f};
            for (int axis = 0; axis < AXES.length; ++axis) {
                key[1 + axis] = number(where, AXES[axis], fields[2 + axis], -MAX_OFFSET_METRES,
                        MAX_OFFSET_METRES, "m");
            }
            int index = tracks.indexOf(track);
            if (index < 0) {
                if (t != 0f || key[1] != 0f || key[2] != 0f || key[3] != 0f) {
                    throw new IllegalArgumentException(where + "track " + track
                            + " must start at t = 0 with offset 0 0 0 (where the body is at the"
                            + " contact), but starts at t = " + fields[0] + " with "
                            + fields[2] + " " + fields[3] + " " + fields[4]);
                }
                tracks.add(track);
                keys.add(new ArrayList<>());
                index = tracks.size() - 1;
            } else {
                List<float[]> before = keys.get(index);
                float previous = before.get(before.size() - 1)[0];
                if (!(t > previous)) {
                    throw new IllegalArgumentException(where + "time t = " + fields[0]
                            + " s of track " + track + " must be later than its previous key"
                            + " at " + previous + " s");
                }
            }
            keys.get(index).add(key);
        }
        if (tracks.isEmpty()) {
            throw new IllegalArgumentException("clip " + name + " has no keys (lines of"
                    + " 't track x y z')");
        }
        float[][] times = new float[tracks.size()][];
        float[][] offsets = new float[tracks.size()][];
        for (int i = 0; i < tracks.size(); ++i) {
            List<float[]> track = keys.get(i);
            if (track.size() < 2) {
                throw new IllegalArgumentException("clip " + name + ": track " + tracks.get(i)
                        + " has 1 key, but needs at least 2 (a motion from t = 0)");
            }
            times[i] = new float[track.size()];
            offsets[i] = new float[3 * track.size()];
            for (int k = 0; k < track.size(); ++k) {
                float[] key = track.get(k);
                times[i][k] = key[0];
                offsets[i][3 * k] = key[1];
                offsets[i][3 * k + 1] = key[2];
                offsets[i][3 * k + 2] = key[3];
            }
        }
        return new Clip(name, tracks.toArray(new String[0]), times, offsets);
    }

    private static float number(String where, String what, String field, float min, float max,
            String unit) {
        float value;
        try {
            value = Float.parseFloat(field);
        } catch (NumberFormatException e) {
            value = Float.NaN;
        }
        if (!(value >= min && value <= max)) {
            throw new IllegalArgumentException(where + what + " '" + field + "' must be a number"
                    + " from " + (int) min + " to " + (int) max + " " + unit);
        }
        return value;
    }
}
