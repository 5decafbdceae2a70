// The scattering-orders LUT's parameterisation and lookups (docs/effects/atmosphere.md, "Multiple
// scattering"), mirroring postfx/src/atmosphere/atmosphere_orders.cpp. Nodes sit at unit coordinates
// i/(n - 1) of: height √((r - ground)/(top - ground)); μ and μs (1 + sign(c)·√|c|)/2 (finer at the
// horizon); azimuth φ/π. The 3D image holds azimuth a's block of μ nodes at x in [a·nμ, (a + 1)·nμ), the
// sun's nodes along y, Rayleigh's height nodes at z in [0, nr), Mie's in [nr, 2nr), and the ground's E≥2
// in slice 2nr; values per unit sun illuminance times the orders' storage scale (radii.w). Expects `atmo`
// and model.glsl.
#ifndef POSTFX_ATMOSPHERE_ORDERS_LOOKUP_GLSL
#define POSTFX_ATMOSPHERE_ORDERS_LOOKUP_GLSL

float ordersUnitFromCosine(float c) {
    return 0.5 + 0.5 * sign(c) * sqrt(min(1.0, abs(c)));
}
float ordersCosineFromUnit(float x) {
    float u = 2.0 * x - 1.0;
    return u * abs(u);
}

// The azimuth's cosine between `dir` and `toSun` about the zenith `up` (1 where either is vertical).
float ordersCosAzimuth(vec3 up, vec3 dir, vec3 toSun) {
    vec3 a = dir - dot(dir, up) * up, b = toSun - dot(toSun, up) * up;
    float la = length(a), lb = length(b);
    if (la < 1e-6 || lb < 1e-6) return 1.0;
    return clamp(dot(a, b) / (la * lb), -1.0, 1.0);
}

// J≥2 per unit length and unit illuminance at planet-centred p (radius r) looking along d: σR·ΨR + σM·ΨM,
// each Ψ bilinear in two azimuth blocks of the trilinear image.
vec3 ordersSource(sampler3D lut, vec3 p, float r, vec3 d, vec3 toSun, AtmosphereMedium m) {
    uvec4 n = atmo.ordersLut;
    vec3 up = p / r;
    float fa = acos(ordersCosAzimuth(up, d, toSun)) * (float(n.w - 1u) / kAtmospherePi);
    float a0 = min(floor(fa), float(n.w - 2u));
    float wa = fa - a0;
    vec3 inverseSize = 1.0 / vec3(float(n.x * n.w), float(n.y), float(2u * n.z + 1u));
    float x = ordersUnitFromCosine(dot(d, up)) * float(n.x - 1u) + 0.5 + a0 * float(n.x);
    float y = (ordersUnitFromCosine(dot(toSun, up)) * float(n.y - 1u) + 0.5) * inverseSize.y;
    float h = clamp((r - atmo.radii.x) / (atmo.radii.y - atmo.radii.x), 0.0, 1.0);
    float z = sqrt(h) * float(n.z - 1u) + 0.5;
    float x1 = x + float(n.x);
    vec3 rayleigh = mix(textureLod(lut, vec3(x * inverseSize.x, y, z * inverseSize.z), 0.0).rgb,
                        textureLod(lut, vec3(x1 * inverseSize.x, y, z * inverseSize.z), 0.0).rgb, wa);
    float zm = (z + float(n.z)) * inverseSize.z;
    vec3 mie = mix(textureLod(lut, vec3(x * inverseSize.x, y, zm), 0.0).rgb,
                   textureLod(lut, vec3(x1 * inverseSize.x, y, zm), 0.0).rgb, wa);
    return (m.rayleighScattering * rayleigh + m.mieScattering * mie) / atmo.radii.w;
}

// E≥2 per unit illuminance at a ground point whose zenith makes cosine muS with the sun.
vec3 ordersGroundIrradiance(sampler3D lut, float muS) {
    uvec4 n = atmo.ordersLut;
    float y = (ordersUnitFromCosine(muS) * float(n.y - 1u) + 0.5) / float(n.y);
    float z = (float(2u * n.z) + 0.5) / float(2u * n.z + 1u);
    return textureLod(lut, vec3(0.5 / float(n.x * n.w), y, z), 0.0).rgb / atmo.radii.w;
}

#endif
