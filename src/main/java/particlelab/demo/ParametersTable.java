package particlelab.demo;

import java.io.IOException;
import java.io.Writer;

/**
 * The settings that made a run, written beside its tables as {@code parameters.csv}
 * ({@link TrajectoryExport}): one row per declared parameter, {@code name,value,unit}, with
 * the value the scene runs with. A number is written as Java writes a float
 * ({@link Float#toString(float)}), which reads back to the same float, so
 * {@code --set name=value} with a row's two fields gives the run the same value to the bit;
 * a named state (a choice) is written by its name, as {@code --set} takes it. The unit is
 * empty for a count, a factor or a choice.
 */
public final class ParametersTable {

    /** The file's name without {@code .csv}. */
    public static final String NAME = "parameters";
    /** The header line: the columns' names. */
    public static final String HEADER = "name,value,unit";

    private ParametersTable() {
    }

    /**
     * Write a parameter's value as {@code --set} reads it back exactly: a choice's name, or
     * the float's shortest decimal form.
     *
     * @param parameter the parameter (not null)
     * @param value its value (one it accepts)
     * @return the text (not null)
     */
    public static String valueText(DemoParameter parameter, float value) {
        if (parameter.isChoice()) {
            return parameter.getChoice(Math.round(value));
        }
        return Float.toString(value);
    }

    /**
     * Write the table: the header, then each parameter's row in declaration order.
     *
     * @param parameters the demo's parameters (not null)
     * @param out where to write (not null; not closed)
     * @return the rows written, header not counted (&ge;0)
     * @throws IOException if writing fails
     */
    public static int writeCsv(DemoParameters parameters, Writer out) throws IOException {
        String newline = System.lineSeparator();
        out.write(HEADER);
        out.write(newline);
        for (int i = 0; i < parameters.size(); ++i) {
            DemoParameter parameter = parameters.get(i);
            out.write(parameter.getName());
            out.write(',');
            out.write(valueText(parameter, parameters.getValueInScene(i)));
            out.write(',');
            out.write(parameter.getUnit());
            out.write(newline);
        }
        return parameters.size();
    }
}
