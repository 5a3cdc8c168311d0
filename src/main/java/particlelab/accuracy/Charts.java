package particlelab.accuracy;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;
import particlelab.files.SafeFiles;

/**
 * The report's charts, drawn headless with XChart to PNG, styled for a projector: white
 * background, large type, one colour and marker per stepper across every chart.
 */
final class Charts {

    /** Log axes cannot show 0: values below this are drawn at it (they are round-off). */
    static final double LOG_FLOOR = 1e-16;
    static final int WIDTH = 900;
    static final int HEIGHT = 640;

    private static final Color[] COLOURS = {new Color(0x1f77b4), new Color(0xd62728),
        new Color(0x2ca02c), new Color(0x9467bd), new Color(0xff7f0e), new Color(0x17becf),
        new Color(0x8c564b), new Color(0x7f7f7f)};
    private static final Marker[] MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND,
        SeriesMarkers.SQUARE, SeriesMarkers.TRIANGLE_UP, SeriesMarkers.TRIANGLE_DOWN,
        SeriesMarkers.CROSS, SeriesMarkers.CIRCLE, SeriesMarkers.SQUARE};

    private Charts() {
    }

    static XYChart create(String title, String xTitle, String yTitle, boolean logX,
            boolean logY) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title)
                .xAxisTitle(xTitle).yAxisTitle(yTitle).build();
        XYStyler styler = chart.getStyler();
        styler.setXAxisLogarithmic(logX);
        styler.setYAxisLogarithmic(logY);
        styler.setPlotBackgroundColor(Color.WHITE);
        styler.setPlotGridLinesColor(new Color(0xdddddd));
        styler.setChartBackgroundColor(Color.WHITE);
        // below the plot, so no legend ever hides a line
        styler.setLegendPosition(Styler.LegendPosition.OutsideS);
        styler.setLegendLayout(Styler.LegendLayout.Horizontal);
        styler.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 20));
        styler.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 15));
        styler.setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 16));
        styler.setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        styler.setMarkerSize(9);
        styler.setAntiAlias(true);
        return chart;
    }

    /**
     * Add a line with markers in the style of slot {@code style} (one per stepper).
     */
    /**
     * A horizontal bar at height y from x = low to x = high, in a style's colour, with no
     * marker and no legend entry: a spread drawn through a point of a line.
     *
     * @param chart the chart (not null, modified)
     * @param name the series' name (unique in the chart)
     * @param low the bar's left end
     * @param high its right end
     * @param y its height
     * @param style the style index of the line it belongs to
     * @return the new series
     */
    static XYSeries horizontalBar(XYChart chart, String name, double low, double high, double y,
            int style) {
        XYSeries series = chart.addSeries(name, new double[] {low, high}, new double[] {y, y});
        series.setLineColor(COLOURS[style % COLOURS.length]);
        series.setMarker(SeriesMarkers.NONE);
        series.setLineStyle(new BasicStroke(1.5f));
        series.setShowInLegend(false);
        return series;
    }

    static XYSeries line(XYChart chart, String name, double[] x, double[] y, int style) {
        XYSeries series = chart.addSeries(name, x, y);
        series.setLineColor(COLOURS[style % COLOURS.length]);
        series.setMarkerColor(COLOURS[style % COLOURS.length]);
        series.setMarker(MARKERS[style % MARKERS.length]);
        series.setLineStyle(new BasicStroke(2.5f));
        return series;
    }

    /**
     * Add a dashed line without markers, for theory.
     */
    static XYSeries dashed(XYChart chart, String name, double[] x, double[] y, int style) {
        XYSeries series = chart.addSeries(name, x, y);
        series.setLineColor(COLOURS[style % COLOURS.length]);
        series.setMarker(SeriesMarkers.NONE);
        series.setLineStyle(SeriesLines.DASH_DASH);
        return series;
    }

    /**
     * Add markers only, no line.
     */
    static XYSeries markers(XYChart chart, String name, double[] x, double[] y, int style) {
        XYSeries series = chart.addSeries(name, x, y);
        series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        series.setMarkerColor(COLOURS[style % COLOURS.length]);
        series.setMarker(MARKERS[style % MARKERS.length]);
        return series;
    }

    static double[] floored(double[] values) {
        double[] result = new double[values.length];
        for (int i = 0; i < values.length; ++i) {
            result[i] = Math.max(LOG_FLOOR, Math.abs(values[i]));
        }
        return result;
    }

    /** Write a chart as a PNG, created new ({@link SafeFiles}: never through a link). */
    static void save(XYChart chart, Path file) throws IOException {
        try (OutputStream out = SafeFiles.create(file, false)) {
            BitmapEncoder.saveBitmap(chart, out, BitmapEncoder.BitmapFormat.PNG);
        }
    }

    /** Write charts side by side as one PNG, created new as {@link #save} does. */
    static void saveGrid(List<XYChart> charts, int rows, int columns, Path file)
            throws IOException {
        try (OutputStream out = SafeFiles.create(file, false)) {
            BitmapEncoder.saveBitmap(charts, rows, columns, out,
                    BitmapEncoder.BitmapFormat.PNG);
        }
    }
}
