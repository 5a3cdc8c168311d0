package particlelab.world;

import com.jme3.math.Vector3f;
import particlelab.collision.SphereTests;
import particlelab.collision.Surface;

/**
 * Every pair of bodies against each other, as spheres of their radii. Pairs are tested all
 * against all, which suits the few bodies of a lecture scene.
 */
public final class SphereRule implements CollisionRule {

    private final ContactResponse response;
    private final Detection detection;
    /** Scratch: A's segment start at the common fraction (m). */
    private final Vector3f startA = new Vector3f();
    /** Scratch: B's segment start at the common fraction (m). */
    private final Vector3f startB = new Vector3f();
    /** Scratch: the relative position at the touch (m). */
    private final Vector3f relative = new Vector3f();
    /** Scratch: the relative velocity (m/s). */
    private final Vector3f relativeVelocity = new Vector3f();

    /**
     * Create a rule.
     *
     * @param response how contacts are resolved (not null)
     * @param detection how contacts are detected (not null)
     */
    public SphereRule(ContactResponse response, Detection detection) {
        if (response == null || detection == null) {
            throw new IllegalArgumentException("response and detection must not be null, but"
                    + " were " + response + ", " + detection);
        }
        this.response = response;
        this.detection = detection;
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
    public void detect(World world, float stepSeconds, Contacts out) {
        int count = world.countBodies();
        for (int i = 0; i < count; ++i) {
            Body a = world.getBody(i);
            if (a.isHeld()) {
                continue;
            }
            for (int k = i + 1; k < count; ++k) {
                Body b = world.getBody(k);
                if (b.isHeld() || a.getInverseMass() == 0f && b.getInverseMass() == 0f) {
                    continue;
                }
                float reach = a.getRadius() + b.getRadius();
                if (detection == Detection.SWEPT) {
                    detectSwept(a, b, reach, stepSeconds, out);
                } else {
                    Contact contact = out.add();
                    double depth = SphereTests.overlap(a.particle.position, b.particle.position,
                            reach, contact.normal);
                    if (depth < 0.0) {
                        out.removeLast();
                        continue;
                    }
                    contact.fraction = 1f;
                    contact.swept = false;
                    fill(contact, a, b, (float) depth);
                }
            }
        }
    }

    @Override
    public void refresh(Contact contact) {
        Body a = contact.bodyA;
        Body b = contact.bodyB;
        double depth = a.getRadius() + b.getRadius()
                - (double) a.particle.position.distance(b.particle.position);
        contact.penetrationNow = (float) Math.max(0.0, depth);
        contact.closingNow = -relativeVelocity.set(a.particle.velocity)
                .subtractLocal(b.particle.velocity).dot(contact.normal);
    }

    @Override
    public String describe() {
        return "spheres, " + detection.name().toLowerCase() + ", " + response.describe();
    }

    private void detectSwept(Body a, Body b, float reach, float stepSeconds, Contacts out) {
        float from = Math.max(a.sweepFraction, b.sweepFraction);
        a.positionAt(from, stepSeconds, startA);
        b.positionAt(from, stepSeconds, startB);
        Vector3f endA = a.particle.position;
        Vector3f endB = b.particle.position;
        double u = SphereTests.sweep(startA, endA, startB, endB, reach);
        if (u == Surface.NO_HIT) {
            return;
        }
        Contact contact = out.add();
        contact.fraction = (float) (from + u * (1.0 - from));
        contact.swept = true;
        // The normal at the touch: the relative position there, from B to A.
        float uf = (float) u;
        relative.set(startA.x + uf * (endA.x - startA.x) - startB.x - uf * (endB.x - startB.x),
                startA.y + uf * (endA.y - startA.y) - startB.y - uf * (endB.y - startB.y),
                startA.z + uf * (endA.z - startA.z) - startB.z - uf * (endB.z - startB.z));
        double depth = 0.0;
        if (u == 0.0) {
            depth = Math.max(0.0, reach - (double) relative.length());
        }
        float length = relative.length();
        if (length > 0f) {
            contact.normal.set(relative).divideLocal(length);
        } else {
            contact.normal.set(Vector3f.UNIT_Y);
        }
        fill(contact, a, b, (float) depth);
    }

    private void fill(Contact contact, Body a, Body b, float depth) {
        contact.rule = this;
        contact.bodyA = a;
        contact.bodyB = b;
        contact.surface = null;
        contact.approachSpeed = -relativeVelocity.set(a.particle.velocity)
                .subtractLocal(b.particle.velocity).dot(contact.normal);
        contact.closingNow = contact.approachSpeed;
        contact.penetrationMetres = depth;
        contact.penetrationNow = depth;
    }
}
