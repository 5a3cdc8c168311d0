package particlelab.world;

import com.jme3.math.Vector3f;
import java.util.ArrayList;
import java.util.List;
import particlelab.collision.Plane;
import particlelab.collision.Surface;

/**
 * Every body against one static surface (infinite mass): the ground, a wall, a slanted plane,
 * a thin wall. The lecture's ground is {@code new SurfaceRule(Plane.ground(), response,
 * detection)}.
 */
public final class SurfaceRule implements CollisionRule {

    private final Surface surface;
    private final ContactResponse response;
    private final Detection detection;
    private final String name;
    private boolean oneWay;
    private int group = Body.DEFAULT_GROUP;
    private int mask = Body.ALL_GROUPS;
    /** Scratch: a body's position at the touch (m). */
    private final Vector3f touch = new Vector3f();
    /** Scratch: the normal of a refresh (unused result). */
    private final Vector3f refreshNormal = new Vector3f();
    /** The only bodies the rule looks at, or null for every body of the world. */
    private List<Body> members;

    /**
     * Create a rule.
     *
     * @param name what the HUD calls the surface, e.g. "ground" (not null)
     * @param surface the surface (not null)
     * @param response how contacts are resolved (not null)
     * @param detection how contacts are detected (not null)
     */
    public SurfaceRule(String name, Surface surface, ContactResponse response,
            Detection detection) {
        if (name == null || surface == null || response == null || detection == null) {
            throw new IllegalArgumentException("name, surface, response and detection must"
                    + " not be null, but were " + name + ", " + surface + ", " + response + ", "
                    + detection);
        }
        this.name = name;
        this.surface = surface;
        this.response = response;
        this.detection = detection;
    }

    /**
     * Create the lecture's ground, the plane {@code y = 0}.
     *
     * @param response how contacts are resolved (not null)
     * @param detection how contacts are detected (not null)
     * @return a new rule (not null)
     */
    public static SurfaceRule ground(ContactResponse response, Detection detection) {
        return new SurfaceRule("ground", Plane.ground(), response, detection);
    }

    /**
     * Return what the HUD calls the surface.
     *
     * @return the name given, e.g. "ground" (not null)
     */
    public String getName() {
        return name;
    }

    /**
     * Access the surface.
     *
     * @return the surface (not null)
     */
    public Surface getSurface() {
        return surface;
    }

    /**
     * Make the surface one-way (bodies coming from behind its front normal pass) or two-way.
     *
     * @param newOneWay true for one-way
     * @return this
     */
    public SurfaceRule setOneWay(boolean newOneWay) {
        oneWay = newOneWay;
        return this;
    }

    /**
     * Alter the surface's collision filter (see {@link Body#setCollisionFilter}).
     *
     * @param newGroup the groups the surface belongs to (bits)
     * @param newMask the groups it may touch (bits)
     * @return this
     */
    public SurfaceRule setCollisionFilter(int newGroup, int newMask) {
        group = newGroup;
        mask = newMask;
        return this;
    }

    /**
     * Make the rule look only at the bodies added this way (the others never touch it, and no
     * contact of theirs is detected or logged): e.g. the lecture's ground stop for the
     * particles that stop there, beside a demo's other rules. Call while building a scene.
     *
     * @param body a body of the world the rule is for (not null)
     * @return this
     */
    public SurfaceRule limitTo(Body body) {
        if (body == null) {
            throw new IllegalArgumentException("body must be a body, but was null");
        }
        if (members == null) {
            members = new ArrayList<>();
        }
        if (!members.contains(body)) {
            members.add(body);
        }
        return this;
    }

    @Override
    public Detection getDetection() {
        return detection;
    }

    @Override
    public ContactResponse getResponse() {
        return response;
    }

    @Override
    public int getGroup() {
        return group;
    }

    @Override
    public int getMask() {
        return mask;
    }

    @Override
    public boolean isOneWay() {
        return oneWay;
    }

    @Override
    public void detect(World world, float stepSeconds, Contacts out) {
        int count = members == null ? world.countBodies() : members.size();
        for (int i = 0; i < count; ++i) {
            Body body = members == null ? world.getBody(i) : members.get(i);
            if (body.getInverseMass() == 0f || !body.isInWorld()) {
                continue;
            }
            float radius = body.getRadius();
            Vector3f end = body.particle.position;
            if (detection == Detection.SWEPT) {
                Contact contact = out.add();
                double u = surface.sweep(body.sweepStart, end, radius, contact.normal);
                if (u == Surface.NO_HIT) {
                    out.removeLast();
                    continue;
                }
                float start = body.sweepFraction;
                contact.fraction = (float) (start + u * (1.0 - start));
                contact.swept = true;
                fill(contact, body, 0f);
                if (u == 0.0) {
                    double depth = surface.overlap(body.sweepStart, radius, touch);
                    contact.penetrationMetres = (float) Math.max(0.0, depth);
                    contact.penetrationNow = contact.penetrationMetres;
                }
            } else {
                Contact contact = out.add();
                double depth = surface.overlap(end, radius, contact.normal);
                if (depth < 0.0) {
                    out.removeLast();
                    continue;
                }
                contact.fraction = 1f;
                contact.swept = false;
                fill(contact, body, (float) depth);
            }
        }
    }

    @Override
    public void refresh(Contact contact) {
        Body body = contact.bodyA;
        double depth = surface.overlap(body.particle.position, body.getRadius(), refreshNormal);
        contact.penetrationNow = (float) Math.max(0.0, depth);
        contact.closingNow = -body.particle.velocity.dot(contact.normal);
    }

    @Override
    public String describe() {
        return name + ": " + surface.describe() + ", " + detection.name().toLowerCase()
                + (oneWay ? ", one-way" : "") + ", " + response.describe();
    }

    private void fill(Contact contact, Body body, float depth) {
        contact.rule = this;
        contact.bodyA = body;
        contact.bodyB = null;
        contact.surface = surface;
        contact.approachSpeed = -body.particle.velocity.dot(contact.normal);
        contact.closingNow = contact.approachSpeed;
        contact.penetrationMetres = depth;
        contact.penetrationNow = depth;
    }
}
