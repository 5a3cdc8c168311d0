package particlelab.view;

/**
 * What the parameter panel shows and changes: rows of numbers with a selection, each row
 * printable and settable from a slider's place. The demo's parameters implement it; the panel
 * ({@link ParameterPanel}) only reads and forwards, so the model is tested without jME.
 */
public interface ParameterPanelModel {

    /** @return how many rows (&ge;0) */
    int countRows();

    /** @return the selected row (&ge;0; 0 when there are none) */
    int getSelected();

    /**
     * Select a row, as a click on its slider does.
     *
     * @param row which (&ge;0, &lt;{@link #countRows()})
     */
    void select(int row);

    /**
     * Return where a row's value sits on its slider.
     *
     * @param row which (&ge;0, &lt;{@link #countRows()})
     * @return from 0 (left) to 1 (right)
     */
    float getSliderFraction(int row);

    /**
     * Set a row's value from its slider's place (rounded to the row's steps).
     *
     * @param row which (&ge;0, &lt;{@link #countRows()})
     * @param fraction from 0 (left) to 1 (right)
     */
    void setSliderFraction(int row, float fraction);

    /**
     * Return what one click on a slider's end button moves it by.
     *
     * @param row which (&ge;0, &lt;{@link #countRows()})
     * @return a share of the slider (&gt;0, &le;1): one step or stop of the row
     */
    float getSliderStep(int row);

    /**
     * Write a row's text (selection mark, name, value, label), allocating nothing.
     *
     * @param row which (&ge;0, &lt;{@link #countRows()})
     * @param text where to append (not null, modified)
     * @return text
     */
    StringBuilder formatRow(int row, StringBuilder text);

    /** @return a number that changes whenever a value or the selection does */
    int getVersion();
}
