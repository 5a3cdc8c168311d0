package particlelab.view;

import com.jme3.app.Application;
import com.jme3.font.BitmapFont;
import com.jme3.math.ColorRGBA;
import com.jme3.math.Vector3f;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.simsilica.lemur.Axis;
import com.simsilica.lemur.Button;
import com.simsilica.lemur.Container;
import com.simsilica.lemur.DefaultRangedValueModel;
import com.simsilica.lemur.FillMode;
import com.simsilica.lemur.GuiGlobals;
import com.simsilica.lemur.HAlignment;
import com.simsilica.lemur.Insets3f;
import com.simsilica.lemur.Label;
import com.simsilica.lemur.Slider;
import com.simsilica.lemur.component.QuadBackgroundComponent;
import com.simsilica.lemur.component.SpringGridLayout;
import com.simsilica.lemur.core.VersionedReference;
import com.simsilica.lemur.focus.FocusNavigationState;
import java.util.ArrayList;
import java.util.List;

/**
 * The parameter panel's mouse half, drawn with Lemur in the HUD's side panel slot: a row of
 * buttons (pause, step, reset, fire, next demo), then one line of text and one slider per row
 * of its {@link ParameterPanelModel}, then a text block (the kept shots' legend). It only
 * reads and forwards: a slider moved sets its row through the model, and the texts and the
 * sliders follow the model when its version changes, so keys and mouse always agree.
 *
 * <p>The style is built here in code (a dark translucent panel in the HUD's font) instead of
 * Lemur's "glass" style, which is a groovy script and would need a scripting engine at every
 * start. {@link #refresh()} allocates nothing while nothing changed.
 */
public final class ParameterPanel {

    /** The panel's width at HUD scale 1 (in pixels), asked of the HUD layout. */
    public static final float WIDTH_AT_SCALE_ONE = 320f;
    /** The panel's text size at HUD scale 1 (in pixels): legible on a projector. */
    public static final float TEXT_SIZE = 17f;
    /**
     * The least text size where the window suits it (in pixels): the lecture hall's 14 px,
     * reached at 1280x720 and up ({@link HudLayout#getPanelScale}).
     */
    public static final float MIN_TEXT_PIXELS = 14f;
    /** The most buttons in one row (more start another row), so every label fits. */
    private static final int BUTTONS_PER_ROW = 4;
    /**
     * A panel taller than its slot is laid out again at the share of its scale that should
     * fit (its height is nearly proportional to it), and at most this share: the smallest
     * step down, so the largest scale that fits is found within 2 % (10 % steps once took
     * drag's 15 rows from 15.3 px, too tall, to 13.8 px at 1280x720)...
     */
    private static final float SHRINK = 0.98f;
    /**
     * ...down to this share of the scale asked for: past it, it reaches below its slot. Drag's
     * 13 rows (with the fault switch and its seed) reached 7.5 px past a 640x360 window at
     * 0.7; a window that small is no lecture hall, and 1280x720 needs no shrinking.
     */
    private static final float SHRINK_FLOOR = 0.6f;
    /** The slider's thumb's width at HUD scale 1 (in pixels). */
    private static final float THUMB_WIDTH = 12f;
    /** A slider's height at HUD scale 1 (in pixels). */
    private static final float SLIDER_HEIGHT = 16f;
    private static final ColorRGBA PANEL_COLOR = new ColorRGBA(0.05f, 0.06f, 0.1f, 0.78f);
    private static final ColorRGBA BUTTON_COLOR = new ColorRGBA(0.22f, 0.3f, 0.45f, 0.95f);
    private static final ColorRGBA SELECTED_COLOR = new ColorRGBA(1f, 0.85f, 0.35f, 1f);
    private static final ColorRGBA TEXT_COLOR = new ColorRGBA(0.9f, 0.92f, 0.95f, 1f);
    private static final ColorRGBA TRACK_COLOR = new ColorRGBA(0.3f, 0.33f, 0.4f, 0.9f);
    private static final ColorRGBA THUMB_COLOR = new ColorRGBA(0.85f, 0.88f, 0.95f, 1f);

    private final ParameterPanelModel model;
    private final BitmapFont font;
    private final Node node = new Node("parameter panel");
    private final Container container;
    private final List<Label> texts = new ArrayList<>();
    private final List<Label> rowLabels = new ArrayList<>();
    private final List<Button> buttons = new ArrayList<>();
    /** The rows of buttons, for the panel's narrowest width. */
    private final List<Container> buttonRows = new ArrayList<>();
    private final Slider[] sliders;
    private final List<VersionedReference<Double>> sliderReferences = new ArrayList<>();
    private final Label heading;
    private final String headingText;
    private final Label legend;
    /** The rows' texts as the model wrote them; the labels show them wrapped to the panel. */
    private final String[] rowTexts;
    /** Measures the texts for wrapping them. */
    private final TextMeasure measure;
    private final StringBuilder scratch = new StringBuilder(128);
    private final Vector3f size = new Vector3f();
    private int shownVersion = Integer.MIN_VALUE;
    private float scale = Float.NaN;
    /** The scale {@link #place} was last asked for (the one used may be smaller). */
    private float askedScale = Float.NaN;
    /** Where the panel was last placed (pixels), so an unchanged slot costs nothing. */
    private final ScreenRect placed = new ScreenRect();
    /** True when the texts changed, so the panel's height must be measured again. */
    private boolean placeAgain = true;
    private boolean legendChanged;
    private final StringBuilder legendText = new StringBuilder(256);
    /** The timeline's text and slider ({@link #addTimeline}), or null. */
    private Label timelineLabel;
    private Slider timeline;
    private VersionedReference<Double> timelineReference;
    private String timelineText = " ";

    /**
     * Build the panel. Call after {@link #initializeLemur} ran for the application.
     *
     * @param model the rows to show and change (not null, live)
     * @param font the HUD's font (not null)
     * @param title the heading, e.g. "Parameters  (F2 hides)" (not null)
     * @param buttonLabels each button's text (not null, same length as buttonActions)
     * @param buttonActions what each button does when clicked (not null, none null)
     */
    public ParameterPanel(ParameterPanelModel model, BitmapFont font, String title,
            List<String> buttonLabels, List<Runnable> buttonActions) {
        if (buttonLabels.size() != buttonActions.size()) {
            throw new IllegalArgumentException("one action per button, but had "
                    + buttonLabels.size() + " labels and " + buttonActions.size()
                    + " actions");
        }
        this.model = model;
        this.font = font;
        this.measure = TextMeasure.of(font);
        this.headingText = title;
        this.rowTexts = new String[model.countRows()];
        java.util.Arrays.fill(rowTexts, "");
        container = new Container(new SpringGridLayout(Axis.Y, Axis.X, FillMode.None,
                FillMode.Even));
        container.setBackground(new QuadBackgroundComponent(PANEL_COLOR));
        heading = text(title, SELECTED_COLOR);
        container.addChild(heading);
        Container row = null;
        for (int i = 0; i < buttonLabels.size(); ++i) {
            if (i % BUTTONS_PER_ROW == 0) {
                row = container.addChild(new Container(new SpringGridLayout(Axis.X, Axis.Y,
                        FillMode.Even, FillMode.Even)));
                buttonRows.add(row);
            }
            Button button = new Button(buttonLabels.get(i));
            Runnable action = buttonActions.get(i);
            button.addClickCommands(source -> action.run());
            button.setBackground(new QuadBackgroundComponent(BUTTON_COLOR));
            button.setFont(font);
            button.setColor(TEXT_COLOR);
            button.setTextHAlignment(HAlignment.Center);
            buttons.add(button);
            row.addChild(button);
        }
        sliders = new Slider[model.countRows()];
        for (int i = 0; i < model.countRows(); ++i) {
            Label label = text("", TEXT_COLOR);
            rowLabels.add(label);
            container.addChild(label);
            Slider slider = new Slider(new DefaultRangedValueModel(0.0, 1.0,
                    model.getSliderFraction(i)), Axis.X);
            slider.setBackground(new QuadBackgroundComponent(TRACK_COLOR));
            slider.setDelta(model.getSliderStep(i));
            slider.getThumbButton().setBackground(new QuadBackgroundComponent(THUMB_COLOR));
            slider.getThumbButton().setText("|");
            slider.getThumbButton().setFont(font);
            slider.getThumbButton().setColor(PANEL_COLOR);
            slider.getIncrementButton().setText(">");
            slider.getDecrementButton().setText("<");
            for (Button end : new Button[] {slider.getIncrementButton(),
                slider.getDecrementButton()}) {
                end.setBackground(new QuadBackgroundComponent(BUTTON_COLOR));
                end.setFont(font);
                end.setColor(TEXT_COLOR);
                buttons.add(end);
            }
            buttons.add(slider.getThumbButton());
            sliders[i] = slider;
            sliderReferences.add(slider.getModel().createReference());
            container.addChild(slider);
        }
        legend = text(" ", TEXT_COLOR);
        container.addChild(legend);
        node.attachChild(container);
    }

    /**
     * Make Lemur ready for an application: once per application, before any panel is built.
     * Lemur keeps one set of globals per JVM, which a new application replaces; an
     * application started while another runs (the C key's headless re-run inside the
     * window) must give the other its globals back when it ends, with the action returned:
     * the window's panel would otherwise find no input or focus in them and throw on its
     * next click (issue 36).
     *
     * @param app the application (not null)
     * @return what puts the globals there before back, if this application's are still
     *     there: run it when the application ends (not null)
     */
    public static Runnable initializeLemur(Application app) {
        GuiGlobals before = GuiGlobals.getInstance();
        GuiGlobals.initialize(app);
        GuiGlobals own = GuiGlobals.getInstance();
        // Lemur's keyboard focus navigation would take Tab and the arrow keys, which the
        // demos use; the panel's keys are the app's own (see the help). A headless
        // application has no such state.
        FocusNavigationState navigation = own.getFocusNavigationState();
        if (navigation != null) {
            navigation.setEnabled(false);
        }
        return () -> {
            if (before != null && GuiGlobals.getInstance() == own) {
                GuiGlobals.setInstance(before);
            }
        };
    }

    /**
     * Add the timeline under the legend: a line of text and a slider over the recorded
     * steps. Call once, before the panel is first placed.
     */
    public void addTimeline() {
        timelineLabel = text(" ", TEXT_COLOR);
        container.addChild(timelineLabel);
        timeline = new Slider(new DefaultRangedValueModel(0.0, 1.0, 1.0), Axis.X);
        timeline.setBackground(new QuadBackgroundComponent(TRACK_COLOR));
        timeline.getThumbButton().setBackground(new QuadBackgroundComponent(SELECTED_COLOR));
        timeline.getThumbButton().setText("|");
        timeline.getThumbButton().setFont(font);
        timeline.getThumbButton().setColor(PANEL_COLOR);
        timeline.getIncrementButton().setText(">");
        timeline.getDecrementButton().setText("<");
        for (Button end : new Button[] {timeline.getIncrementButton(),
            timeline.getDecrementButton()}) {
            end.setBackground(new QuadBackgroundComponent(BUTTON_COLOR));
            end.setFont(font);
            end.setColor(TEXT_COLOR);
            buttons.add(end);
        }
        buttons.add(timeline.getThumbButton());
        timelineReference = timeline.getModel().createReference();
        container.addChild(timeline);
        placeAgain = true;
    }

    /**
     * Show the timeline's text and place; what is set here is no move of the mouse's.
     * Allocates only when the text changed.
     *
     * @param text the line above the slider (not null)
     * @param fraction the slider's place, 0 (the oldest step) to 1 (the newest)
     */
    public void setTimeline(CharSequence text, double fraction) {
        if (timeline == null) {
            return;
        }
        if (!TextFormat.sameText(timelineText, text)) {
            timelineText = text.toString();
            placeAgain = true;
        }
        if (timeline.getModel().getValue() != fraction) {
            timeline.getModel().setValue(fraction);
        }
        timelineReference.update();
    }

    /**
     * Return where the mouse moved the timeline's slider since the last call, once.
     *
     * @return the place (0 to 1), or NaN if it was not moved
     */
    public double takeTimelineMove() {
        if (timeline == null || !timelineReference.update()) {
            return Double.NaN;
        }
        return timeline.getModel().getValue();
    }

    /**
     * Move the timeline's slider, as the mouse does (for tests).
     *
     * @param fraction the place, from 0 (left) to 1 (right)
     */
    public void dragTimeline(double fraction) {
        timeline.getModel().setValue(fraction);
    }

    /** @return the timeline's text as shown (empty without a timeline) */
    public String getTimelineText() {
        return timelineLabel == null ? "" : timelineText;
    }

    /** @return the live node, to attach to the GUI scene (not null) */
    public Node getNode() {
        return node;
    }

    /**
     * Set the text under the sliders (the kept shots' legend); shown at the next
     * {@link #refresh()} if it changed.
     *
     * @param text the text (not null, copied)
     */
    public void setLegend(CharSequence text) {
        if (!TextFormat.sameText(legendText, text)) {
            legendText.setLength(0);
            legendText.append(text);
            legendChanged = true;
        }
    }

    /**
     * Put the panel into a rectangle of the window, at a HUD scale: its top left corner at
     * the rectangle's, as wide as it is. Allocates nothing unless the scale changed.
     *
     * @param where the side panel slot (not null, not modified; empty hides the panel)
     * @param hudScale the HUD's scale (&gt;0)
     */
    public void place(ScreenRect where, float hudScale) {
        if (where.isEmpty()) {
            node.setCullHint(Spatial.CullHint.Always);
            return;
        }
        node.setCullHint(Spatial.CullHint.Inherit);
        if (!placeAgain && hudScale == askedScale && where.getX() == placed.getX()
                && where.getY() == placed.getY() && where.getWidth() == placed.getWidth()
                && where.getHeight() == placed.getHeight()) {
            return;
        }
        placed.set(where);
        placeAgain = false;
        askedScale = hudScale;
        // As tall as its content needs, as wide as the slot: but never narrower than its
        // buttons and sliders' ends need, or Lemur hands them a negative width and throws on
        // the render thread (a small window's slot is 40 % of it). Then the panel reaches
        // past its slot rather than break. Taller than the slot (many rows, wrapped, in a
        // small window), it is laid out again at a smaller scale, down to a floor.
        float tryScale = hudScale;
        float width = layOutAt(where, tryScale);
        while (size.y > where.getHeight() && tryScale > SHRINK_FLOOR * hudScale) {
            float fitting = tryScale * where.getHeight() / size.y;
            tryScale = Math.max(SHRINK_FLOOR * hudScale, Math.min(fitting, SHRINK * tryScale));
            width = layOutAt(where, tryScale);
        }
        container.setPreferredSize(size.clone());
        container.setLocalTranslation(where.getX(), where.getTop(), 0f);
    }

    /**
     * Size the panel's parts for a scale and measure it in a slot: its width is returned,
     * its content's height left in {@link #size}.
     */
    private float layOutAt(ScreenRect where, float tryScale) {
        if (tryScale != scale) {
            applyScale(tryScale);
        }
        float width = Math.max(where.getWidth(), minimumWidth());
        wrapTexts(width);
        container.setPreferredSize(null);
        size.set(width, container.getPreferredSize().y, 0f);
        return width;
    }

    /** Size the texts, buttons, sliders and insets for a scale. Allocates. */
    private void applyScale(float newScale) {
        scale = newScale;
        float textSize = TEXT_SIZE * newScale;
        for (int i = 0; i < texts.size(); ++i) {
            texts.get(i).setFontSize(textSize);
        }
        for (int i = 0; i < buttons.size(); ++i) {
            buttons.get(i).setFontSize(textSize);
            buttons.get(i).setInsets(new Insets3f(2f * newScale, 4f * newScale,
                    2f * newScale, 4f * newScale));
        }
        for (Slider slider : sliders) {
            slider.setPreferredSize(new Vector3f(10f, SLIDER_HEIGHT * newScale, 0f));
            slider.getThumbButton().setPreferredSize(new Vector3f(THUMB_WIDTH * newScale,
                    SLIDER_HEIGHT * newScale, 0f));
        }
        if (timeline != null) {
            timeline.setPreferredSize(new Vector3f(10f, SLIDER_HEIGHT * newScale, 0f));
            timeline.getThumbButton().setPreferredSize(new Vector3f(
                    THUMB_WIDTH * newScale, SLIDER_HEIGHT * newScale, 0f));
        }
        container.setInsets(new Insets3f(6f * newScale, 8f * newScale, 6f * newScale,
                8f * newScale));
    }

    /**
     * Return the narrowest the panel can be laid out: the container's insets and its widest
     * row of buttons or slider's two end buttons and thumb, at their natural widths.
     *
     * @return the width (in pixels, &ge;0)
     */
    private float minimumWidth() {
        float widest = 0f;
        for (int i = 0; i < buttonRows.size(); ++i) {
            widest = Math.max(widest, buttonRows.get(i).getPreferredSize().x);
        }
        for (Slider slider : sliders) {
            widest = Math.max(widest, sliderEnds(slider));
        }
        if (timeline != null) {
            widest = Math.max(widest, sliderEnds(timeline));
        }
        Insets3f insets = container.getInsets();
        float sides = insets == null ? 0f : insets.min.x + insets.max.x;
        return widest + sides;
    }

    private static float sliderEnds(Slider slider) {
        return slider.getDecrementButton().getPreferredSize().x
                + slider.getIncrementButton().getPreferredSize().x
                + slider.getThumbButton().getPreferredSize().x;
    }

    /** @return the text size of the last {@link #place} (in pixels; NaN before it) */
    public float getTextSize() {
        return TEXT_SIZE * scale;
    }

    /**
     * Follow the model and the sliders: a slider the mouse moved sets its row (and selects
     * it); a model that changed rewrites the texts and moves the sliders. Call once a frame;
     * allocates nothing while nothing changed.
     */
    public void refresh() {
        for (int i = 0; i < sliders.length; ++i) {
            if (sliderReferences.get(i).update()) {
                model.select(i);
                model.setSliderFraction(i, (float) sliders[i].getModel().getValue());
            }
        }
        if (model.getVersion() != shownVersion) {
            shownVersion = model.getVersion();
            for (int i = 0; i < sliders.length; ++i) {
                scratch.setLength(0);
                rowTexts[i] = model.formatRow(i, scratch).toString();
                rowLabels.get(i).setColor(i == model.getSelected() ? SELECTED_COLOR
                        : TEXT_COLOR);
                sliders[i].getModel().setValue(model.getSliderFraction(i));
                // What the model set is no change of the mouse's.
                sliderReferences.get(i).update();
            }
            // The texts may need another height: size the panel again at the next place.
            placeAgain = true;
        }
        if (legendChanged) {
            legendChanged = false;
            placeAgain = true;
        }
    }

    /** @return how many rows of text and sliders the panel shows */
    public int countRows() {
        return sliders.length;
    }

    /**
     * Return the text of a row as shown (for tests).
     *
     * @param row which (&ge;0, &lt;the model's row count)
     * @return the text (not null)
     */
    public String getRowText(int row) {
        return rowTexts[row];
    }

    /**
     * Return a row's text as drawn: wrapped to the panel's width at the last {@link #place}.
     *
     * @param row which (&ge;0, &lt;the model's row count)
     * @return the text, lines separated by '\n' (not null)
     */
    public String getShownRowText(int row) {
        return rowLabels.get(row).getText();
    }

    /** @return the legend (not null; a space when empty) */
    public String getLegendText() {
        return legendText.length() == 0 ? " " : legendText.toString();
    }

    /**
     * Access the panel's Lemur container, whose children are its heading, rows of buttons,
     * texts and sliders, top to bottom (for layout tests).
     *
     * @return the live container (do not modify)
     */
    public Container getContainer() {
        return container;
    }

    /**
     * Click a button, as the mouse does (for tests and scripted runs).
     *
     * @param label the button's text (one of those given)
     */
    public void click(String label) {
        for (int i = 0; i < buttons.size(); ++i) {
            if (label.equals(buttons.get(i).getText())) {
                buttons.get(i).click();
                return;
            }
        }
        throw new IllegalArgumentException("no button \"" + label + "\"");
    }

    /**
     * Move a slider, as the mouse does (for tests).
     *
     * @param row which (&ge;0, &lt;the model's row count)
     * @param fraction the place, from 0 (left) to 1 (right)
     */
    public void drag(int row, float fraction) {
        sliders[row].getModel().setValue(fraction);
    }

    /**
     * Copy the panel's screen rectangle, as last placed and sized (for layout tests).
     *
     * @param storeResult storage for the result (not null, modified)
     * @return storeResult (empty when hidden)
     */
    public ScreenRect copyRect(ScreenRect storeResult) {
        if (node.getCullHint() == Spatial.CullHint.Always) {
            return storeResult.set(0f, 0f, 0f, 0f);
        }
        Vector3f at = container.getLocalTranslation();
        Vector3f extent = container.getPreferredSize();
        return storeResult.set(at.x, at.y - extent.y, extent.x, extent.y);
    }

    /**
     * Give every label its text wrapped to the panel's inner width, with explicit line
     * breaks, so Lemur sizes each label for all its lines: a label Lemur wraps itself keeps
     * the height of one line and its other lines cover what lies below (a slider, the
     * timeline's text). Allocates only when placing anew.
     *
     * @param panelWidth the panel's width (in pixels)
     */
    private void wrapTexts(float panelWidth) {
        Insets3f insets = container.getInsets();
        float sides = insets == null ? 0f : insets.min.x + insets.max.x;
        float textWidth = Math.max(1f, panelWidth - sides);
        float textSize = TEXT_SIZE * scale;
        heading.setText(wrap(headingText, textSize, textWidth));
        for (int i = 0; i < rowTexts.length; ++i) {
            rowLabels.get(i).setText(wrap(rowTexts[i], textSize, textWidth));
        }
        legend.setText(wrap(getLegendText(), textSize, textWidth));
        if (timelineLabel != null) {
            timelineLabel.setText(wrap(timelineText, textSize, textWidth));
        }
    }

    /**
     * Break a text's lines at spaces so that none is wider than a width (a single word wider
     * than it stays whole on its own line).
     */
    private String wrap(String text, float textSize, float maxWidth) {
        if (measure.width(text, textSize) <= maxWidth) {
            return text;
        }
        StringBuilder wrapped = new StringBuilder(text.length() + 8);
        StringBuilder line = new StringBuilder();
        for (String paragraph : text.split("\n", -1)) {
            if (wrapped.length() > 0) {
                wrapped.append('\n');
            }
            line.setLength(0);
            for (String word : paragraph.split(" ", -1)) {
                int before = line.length();
                if (before > 0) {
                    line.append(' ');
                }
                line.append(word);
                if (before > 0 && measure.width(line, textSize) > maxWidth) {
                    line.setLength(before);
                    wrapped.append(line).append('\n');
                    line.setLength(0);
                    line.append(word);
                }
            }
            wrapped.append(line);
        }
        return wrapped.toString();
    }

    private Label text(String value, ColorRGBA color) {
        Label label = new Label(value);
        label.setFont(font);
        label.setColor(color);
        texts.add(label);
        return label;
    }
}
