package particlelab;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * Records what a logger logs while some code runs, without printing it on the test console,
 * and puts the logger back as it was afterwards.
 */
public final class LogRecords {

    private LogRecords() {
    }

    /**
     * Run code with every record of the logger at or above a level captured.
     *
     * @param logger the logger (not null; its level, handlers and parent flag are restored)
     * @param level the lowest level to record (not null)
     * @param code what to run (not null)
     * @return the records, in the order logged
     */
    public static List<LogRecord> during(Logger logger, Level level, Runnable code) {
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
        Level oldLevel = logger.getLevel();
        boolean oldUseParent = logger.getUseParentHandlers();
        logger.setLevel(level);
        logger.setUseParentHandlers(false);
        logger.addHandler(recorder);
        try {
            code.run();
        } finally {
            logger.removeHandler(recorder);
            logger.setUseParentHandlers(oldUseParent);
            logger.setLevel(oldLevel);
        }
        return records;
    }
}
