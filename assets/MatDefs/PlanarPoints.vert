#import "Common/ShaderLib/GLSLCompat.glsllib"

// One float each: x, y and z of the point (in metres, model space).
attribute float inPosition;
attribute float inTexCoord;
attribute float inTexCoord2;
// R, G, B, A from unsigned bytes, normalised to 0 to 1.
attribute vec4 inColor;

uniform mat4 g_WorldViewProjectionMatrix;
// Each point's size on the screen (in pixels).
uniform float m_PointSize;

varying vec4 vertColor;

void main() {
    vertColor = inColor;
    gl_PointSize = m_PointSize;
    gl_Position = g_WorldViewProjectionMatrix * vec4(inPosition, inTexCoord, inTexCoord2, 1.0);
}
