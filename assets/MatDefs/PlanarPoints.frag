#import "Common/ShaderLib/GLSLCompat.glsllib"

varying vec4 vertColor;

void main() {
    gl_FragColor = vertColor;
}
