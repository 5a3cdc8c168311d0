package particlelab.app;

import com.jme3.post.SceneProcessor;
import com.jme3.profile.AppProfiler;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.Renderer;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.texture.FrameBuffer;
import com.jme3.texture.Image;
import com.jme3.util.BufferUtils;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import javax.imageio.ImageIO;
import particlelab.files.SafeFiles;

/**
 * Reads the finished frame back from the GPU when asked and writes it as a PNG, then measures
 * it: the number of distinct colours and the share of the most common one, so a script can
 * tell a rendered scene from a blank window. Attach it to the last viewport (the GUI's) so
 * the HUD is in the picture.
 */
public final class ScreenshotCapture implements SceneProcessor {

    private final File file;
    private boolean replace;
    private Renderer renderer;
    private int width;
    private int height;
    private boolean requested;
    private boolean written;
    private String statistics = "";
    private IOException failure;

    /**
     * Create a capture.
     *
     * @param file where to write the PNG (not null)
     */
    public ScreenshotCapture(File file) {
        this.file = file;
    }

    /**
     * Allow an existing regular file at the path to be replaced ({@code --force}); a symbolic
     * link, a folder or a device there is refused even so ({@link SafeFiles}).
     *
     * @param allowed true to replace, false (the default) to refuse an existing file
     */
    public void setReplace(boolean allowed) {
        replace = allowed;
    }

    /** Capture the next frame to finish rendering. */
    public void request() {
        requested = true;
    }

    /** @return true once the PNG was written */
    public boolean isWritten() {
        return written;
    }

    /** @return the failure to write the file, or null */
    public IOException getFailure() {
        return failure;
    }

    /** @return the pixel statistics line, empty before the capture (not null) */
    public String getStatistics() {
        return statistics;
    }

    @Override
    public void initialize(RenderManager renderManager, ViewPort viewPort) {
        renderer = renderManager.getRenderer();
        width = viewPort.getCamera().getWidth();
        height = viewPort.getCamera().getHeight();
    }

    @Override
    public void reshape(ViewPort viewPort, int newWidth, int newHeight) {
        width = newWidth;
        height = newHeight;
    }

    @Override
    public boolean isInitialized() {
        return renderer != null;
    }

    @Override
    public void preFrame(float tpf) {
    }

    @Override
    public void postQueue(RenderQueue renderQueue) {
    }

    @Override
    public void postFrame(FrameBuffer out) {
        if (!requested) {
            return;
        }
        requested = false;
        ByteBuffer pixels = BufferUtils.createByteBuffer(width * height * 4);
        renderer.readFrameBufferWithFormat(out, pixels, Image.Format.RGBA8);
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Map<Integer, Integer> counts = new HashMap<>();
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                int base = ((height - 1 - y) * width + x) * 4;
                int rgb = (pixels.get(base) & 0xff) << 16 | (pixels.get(base + 1) & 0xff) << 8
                        | (pixels.get(base + 2) & 0xff);
                image.setRGB(x, y, rgb);
                counts.merge(rgb, 1, Integer::sum);
            }
        }
        int most = 0;
        for (int count : counts.values()) {
            most = Math.max(most, count);
        }
        statistics = String.format("%dx%d pixels, %d distinct colours,"
                + " the most common covers %.1f%%", width, height, counts.size(),
                100.0 * most / (width * height));
        try {
            writePng(image, file.toPath(), replace);
            written = true;
        } catch (IOException e) {
            failure = e;
        }
    }

    @Override
    public void cleanup() {
    }

    @Override
    public void setProfiler(AppProfiler profiler) {
    }

    /**
     * Write a picture as a PNG by the rules of {@link SafeFiles}: created new, never through a
     * symbolic link, an existing regular file replaced only if allowed.
     *
     * @param image the picture (not null)
     * @param path where (not null; its folder exists)
     * @param replace true if an existing regular file may be replaced
     * @throws IOException if it cannot be written or is refused (the message says why)
     */
    static void writePng(BufferedImage image, Path path, boolean replace) throws IOException {
        // Our own stream: ImageIO.write(File) deletes what is at the path first (an empty
        // folder included) and prints a stack trace when it cannot open the file.
        ImageIO.setUseCache(false);
        try (OutputStream stream = SafeFiles.create(path, replace)) {
            if (!ImageIO.write(image, "png", stream)) {
                throw new IOException("no PNG writer is installed");
            }
        }
    }
}
