package particlelab.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.jme3.math.Vector3f;
import java.io.IOException;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import particlelab.Allocations;
import particlelab.physics.Gravity;
import particlelab.physics.Particle;
import particlelab.physics.ParticleIntegrator;

class TrajectoryRecordTest {

    private static final float H = 1f / 60f;

    @Test
    void rowsAreTheLaunchThenEachStepWithTimeFromTheStepCount() throws IOException {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(10f, 10f, 0f), 1f);
        TrajectoryRecord record = new TrajectoryRecord();
        record.begin(particle);
        for (int n = 1; n <= 1000; ++n) {
            integrator.step(particle, H);
            record.add(particle, H);
            // begin() after the first row changes nothing.
            record.begin(particle);
        }
        assertEquals(1001, record.size());
        assertEquals(0f, record.get(0, 0));
        assertEquals(10f, record.get(0, 5));
        // t = n·h from the count, as particle-lab trajectory computes it: a sum of 1000
        // float h would be off in the last digits.
        for (int n = 0; n <= 1000; ++n) {
            assertEquals((float) (n * (double) H), record.get(n, 0), "row " + n);
        }
        assertEquals(particle.position.y, record.get(1000, 2));
        StringWriter csv = new StringWriter();
        record.writeCsv(csv);
        String[] lines = csv.toString().split(System.lineSeparator());
        assertEquals(TrajectoryRecord.HEADER, lines[0]);
        assertEquals("0.0,0.0,0.0,0.0,10.0,10.0,0.0", lines[1]);
        assertEquals(1002, lines.length);
    }

    @Test
    void aChangeOfHStartsTheCountAgainFromTheTimeReached() {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 1f);
        TrajectoryRecord record = new TrajectoryRecord();
        record.begin(particle);
        for (int n = 0; n < 30; ++n) {
            record.add(particle, H);
        }
        record.add(particle, 0.5f);
        record.add(particle, H);
        double base = 30 * (double) H;
        assertEquals((float) (base + 0.5), record.get(31, 0));
        assertEquals((float) (base + 0.5 + H), record.get(32, 0));
    }

    @Test
    void pastTheCapTheFirstRowsStayAndLaterStepsAreCounted() {
        Particle particle = new Particle(Vector3f.ZERO, Vector3f.UNIT_X, 1f);
        TrajectoryRecord record = new TrajectoryRecord();
        record.begin(particle);
        int extra = 100;
        for (int n = 1; n < TrajectoryRecord.MAX_ROWS + extra; ++n) {
            particle.position.x = n;
            record.add(particle, H);
        }
        assertEquals(TrajectoryRecord.MAX_ROWS, record.size());
        assertEquals(extra, record.countDropped());
        assertEquals(TrajectoryRecord.MAX_ROWS - 1, record.get(TrajectoryRecord.MAX_ROWS - 1, 1));
        record.clear();
        assertEquals(0, record.size());
        assertEquals(0L, record.countDropped());
    }

    @Test
    void recordingAllocatesNothingOnceTheArrayHasGrown() {
        ParticleIntegrator integrator = new ParticleIntegrator(new Gravity());
        Particle particle = new Particle(Vector3f.ZERO, new Vector3f(10f, 10f, 0f), 1f);
        TrajectoryRecord record = new TrajectoryRecord();
        int steps = 10 * TrajectoryRecord.INITIAL_ROWS;
        Runnable flight = () -> {
            record.clear();
            particle.position.zero();
            particle.velocity.set(10f, 10f, 0f);
            record.begin(particle);
            for (int n = 0; n < steps; ++n) {
                integrator.step(particle, H);
                record.add(particle, H);
            }
        };
        // The first flight grows the array; every later one reuses it.
        flight.run();
        Allocations.assertAllocatesNothing(steps + " recorded steps", flight);
    }

    @Test
    void fileSafeNamesKeepLettersDigitsDotsAndHyphens() {
        assertEquals("linear-drag-f-0.9-v", TrajectoryExport.fileSafeName(
                "linear drag  F = -0.9 V"));
        assertEquals("quadratic-drag-f-0.064-v-v", TrajectoryExport.fileSafeName(
                "quadratic drag  F = -0.064 |V|V"));
        assertEquals("ball", TrajectoryExport.fileSafeName("ball"));
        assertEquals("a-b", TrajectoryExport.fileSafeName("../a/b/.."));
        assertEquals("particle", TrajectoryExport.fileSafeName("ω = |·|"));
    }
}
