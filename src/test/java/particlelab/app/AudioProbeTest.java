package particlelab.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import org.junit.jupiter.api.Test;

class AudioProbeTest {

    @Test
    void aSilentStartIsNotedBelowTheLevelJavaLoggingPrintsByDefault() {
        List<LogRecord> records = new ArrayList<>();
        Handler recorder = new Handler() {
            @Override
            public void publish(LogRecord record) {
                records.add(record);
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        recorder.setLevel(Level.ALL);
        Level oldLevel = AudioProbe.LOGGER.getLevel();
        AudioProbe.LOGGER.setLevel(Level.ALL);
        // Recorded here only, not printed on the test console too.
        AudioProbe.LOGGER.setUseParentHandlers(false);
        AudioProbe.LOGGER.addHandler(recorder);
        try {
            AudioProbe.noteSilentStart("no sound card or sound server found");
        } finally {
            AudioProbe.LOGGER.removeHandler(recorder);
            AudioProbe.LOGGER.setUseParentHandlers(true);
            AudioProbe.LOGGER.setLevel(oldLevel);
        }
        assertEquals(1, records.size());
        LogRecord record = records.get(0);
        assertEquals(Level.CONFIG, record.getLevel());
        // java.util.logging's default configuration prints INFO and above only.
        assertTrue(record.getLevel().intValue() < Level.INFO.intValue());
        assertTrue(record.getMessage().contains("no sound card or sound server found"),
                record.getMessage());
    }
}
