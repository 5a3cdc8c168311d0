package particlelab.app;

public final class Main {
    public static void main(String[] args) {
        System.out.println("hello " + com.jme3.math.Vector3f.UNIT_X);
    }
}
