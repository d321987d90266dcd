// The default material's vertex stage: glTF's baseColorFactor times COLOR_0 (gl_Color), lit per
// vertex where the mesh has normals, and the base colour texture's coordinates through
// KHR_texture_transform. The uniforms are the scene's (scenes/object_uniforms.h).
uniform vec4 uBaseColorFactor = vec4(1.0);
uniform int uBaseColorTexCoord = 0;        // 0: TEXCOORD_0, 1: gl_MultiTexCoord1
uniform mat3 uTextureTransform = mat3(1.0);
uniform int uLighting = 2;                 // 0: unlit, 1: per vertex on NORMAL, 2: flat, per fragment
uniform mat4 uModelView = mat4(1.0);
uniform mat3 uNormalMatrix = mat3(1.0);
uniform vec4 uUnproject = vec4(1.0, 1.0, 0.0, 1.0);
varying vec4 color;   // linear, lit where lit per vertex
varying vec2 uv;
varying float viewZ;  // the view-space depth, for flat normals

void main(void) {
    vec4 base = uBaseColorFactor * gl_Color;
    vec4 p = uModelView * gl_Vertex;
    if (uLighting == 1) {
        vec3 n = normalize(uNormalMatrix * gl_Normal);
        // Towards the eye: to the origin in perspective, along +z in an orthographic view.
        vec3 toEye = vec3(0.0, 0.0, uUnproject.w) + uUnproject.z * p.xyz;
        // A normal facing away is the back of a double-sided surface, lit as glTF says: reversed.
        if (dot(n, toEye) < 0.0) n = -n;
        base = vec4(base.rgb * lambert(n), base.a);
    }
    color = base;
    vec2 st = uBaseColorTexCoord == 1 ? gl_MultiTexCoord1.st : gl_MultiTexCoord0.st;
    uv = (uTextureTransform * vec3(st, 1.0)).xy;
    viewZ = p.z;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
