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
import java.nio.file.Files;
import java.util.HashMap;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * Reads the finished frame back from the GPU when asked and writes it as a PNG, then measures
 * it: the number of distinct colours and the share of the most common one, so a script can
 * tell a rendered scene from a blank window. Attach it to the last viewport (the GUI's) so
 * the HUD is in the picture.
 */
public final class ScreenshotCapture implements SceneProcessor {

    private final File file;
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
        // Our own stream: ImageIO.write(File) deletes what is at the path first (an empty
        // folder included) and prints a stack trace when it cannot open the file.
        ImageIO.setUseCache(false);
        try {
            File parent = file.getAbsoluteFile().getParentFile();
            if (parent != null) {
                Files.createDirectories(parent.toPath());
            }
            try (OutputStream stream = Files.newOutputStream(file.toPath())) {
                if (!ImageIO.write(image, "png", stream)) {
                    throw new IOException("no PNG writer is installed");
                }
            }
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
}
