// Steps of a ray through the atmosphere crowded toward its lowest point, where the air is densest
// (postfx/src/atmosphere/atmosphere_orders.cpp, orderMarchSteps): the ray split at its lowest point where
// that lies inside [tBegin, tEnd], each part's steps (in proportion to its length, at least one) spaced
// quadratically away from it. tLow = -r·μ for a ray from radius r at cosine μ.
#ifndef POSTFX_ATMOSPHERE_MARCH_STEPS_GLSL
#define POSTFX_ATMOSPHERE_MARCH_STEPS_GLSL

// Step i of `steps` over [tBegin, tEnd], crowded toward the ray's lowest point tLow (orderMarchSteps):
// x: midpoint, y: length.
vec2 marchStep(uint i, uint steps, float tBegin, float tEnd, float tLow) {
    float from, to;
    uint n, q;
    bool reversed;
    if (tLow <= tBegin) {
        from = tBegin, to = tEnd, n = steps, q = i, reversed = false;
    } else if (tLow >= tEnd) {
        from = tEnd, to = tBegin, n = steps, q = i, reversed = true;
    } else {
        uint before =
            uint(clamp(floor(float(steps) * (tLow - tBegin) / (tEnd - tBegin) + 0.5), 1.0, float(steps)));
        uint after = max(1u, steps > before ? steps - before : 1u);
        if (i < before)
            from = tLow, to = tBegin, n = before, q = i, reversed = true;
        else
            from = tLow, to = tEnd, n = after, q = i - before, reversed = false;
    }
    // Boundaries from + (to - from)·(j/n)²; a reversed part runs from j = n down to 0.
    float j0 = reversed ? float(n - q) : float(q), j1 = reversed ? j0 - 1.0 : j0 + 1.0;
    float a = from + (to - from) * (j0 * j0) / float(n * n);
    float b = from + (to - from) * (j1 * j1) / float(n * n);
    return vec2(0.5 * (a + b), abs(b - a));
}

// The number of steps marchStep serves: `steps`, or before + after when the lowest point splits the ray.
uint marchStepCount(uint steps, float tBegin, float tEnd, float tLow) {
    if (tLow <= tBegin || tLow >= tEnd) return steps;
    uint before =
        uint(clamp(floor(float(steps) * (tLow - tBegin) / (tEnd - tBegin) + 0.5), 1.0, float(steps)));
    return before + max(1u, steps > before ? steps - before : 1u);
}

#endif
