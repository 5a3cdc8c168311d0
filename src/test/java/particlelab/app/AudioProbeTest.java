package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.Test;
import particlelab.LogRecords;

class AudioProbeTest {

    @Test
    void aSilentStartIsNotedBelowTheLevelJavaLoggingPrintsByDefault() {
        List<LogRecord> records = LogRecords.during(AudioProbe.LOGGER, Level.ALL,
                () -> AudioProbe.noteSilentStart("no sound card or sound server found"));
        assertEquals(1, records.size());
        LogRecord record = records.get(0);
        assertEquals(Level.CONFIG, record.getLevel());
        // java.util.logging's default configuration prints INFO and above only.
        assertTrue(record.getLevel().intValue() < Level.INFO.intValue());
        assertTrue(record.getMessage().contains("no sound card or sound server found"),
                record.getMessage());
    }
}
