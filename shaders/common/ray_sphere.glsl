// Ray–sphere intersection for the effects that meet spheres (the atmosphere's planet and top, the
// clouds' curved layer); mirrored in double by postfx/src/atmosphere/atmosphere_model.cpp, raySphere.
#ifndef POSTFX_COMMON_RAY_SPHERE_GLSL
#define POSTFX_COMMON_RAY_SPHERE_GLSL

// Ray o + t·d (|d| = 1) against the sphere of `radius` at the origin: (tNear, tFar), or both -1 when it
// misses. The discriminant as radius² - h², h the ray's distance to the centre, and the roots as q and
// c/q, so neither cancels for an origin far from the sphere or on it.
vec2 raySphere(vec3 o, vec3 d, float radius) {
    float b = dot(o, d);
    float h = length(o - b * d);
    float disc = (radius - h) * (radius + h);
    if (disc < 0.0) return vec2(-1.0);
    float len = length(o);
    float c = (len - radius) * (len + radius);
    float q = -b - (b < 0.0 ? -1.0 : 1.0) * sqrt(disc);
    if (q == 0.0) return vec2(0.0);
    float t0 = q, t1 = c / q;
    return vec2(min(t0, t1), max(t0, t1));
}

#endif
