// core/model/frame.cpp in GLSL: orthonormal frames, z = the shading normal. Shared by every
// surface shader.
const float PI = 3.14159265358979;

struct Frame { vec3 x, y, z; };

vec3 toLocal(Frame f, vec3 v) { return vec3(dot(v, f.x), dot(v, f.y), dot(v, f.z)); }
vec3 toWorld(Frame f, vec3 v) { return v.x * f.x + v.y * f.y + v.z * f.z; }

Frame frameFromNormal(vec3 n) {  // Duff et al. 2017, as Frame::fromNormal
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    return Frame(vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y), n);
}

Frame frameFromNormalAndAxis(vec3 n, vec3 axis) {  // as Frame::fromNormalAndAxis
    vec3 t = axis - dot(axis, n) * n;
    float len2 = dot(t, t);
    if (!(len2 > 1e-20) || isinf(len2)) return frameFromNormal(n);
    vec3 x = t * inversesqrt(len2);
    return Frame(x, cross(n, x), n);
}

float pow5(float x) { return (x * x) * (x * x) * x; }
