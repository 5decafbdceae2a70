// The transmittance LUT's texture coordinate (docs/effects/atmosphere.md, "Parameterisations"), for the
// atmosphere's own passes (model.glsl) and for the effects that read the LUT
// (common/medium/atmosphere_light.glsl): Bruneton's horizon mapping x_μ = (d - d_min)/(d_max - d_min), x_r =
// ρ/H with H = √(top² - ground²), ρ = √(r² - ground²), d the distance from radius r along cosine μ to the
// top, d_min = top - r, d_max = ρ + H; each through the texel-centre mapping of a side of `size` texels.
#ifndef POSTFX_ATMOSPHERE_TRANSMITTANCE_LUT_GLSL
#define POSTFX_ATMOSPHERE_TRANSMITTANCE_LUT_GLSL

vec2 transmittanceLutUv(float r, float mu, float ground, float top, vec2 size) {
    r = clamp(r, ground, top);
    float H = sqrt(max(0.0, (top - ground) * (top + ground)));
    float rho = sqrt(max(0.0, (r - ground) * (r + ground)));
    float d = max(0.0, -r * mu + sqrt(max(0.0, (top - r) * (top + r) + r * r * mu * mu)));
    float dMin = top - r, dMax = rho + H;
    vec2 x = vec2(dMax > dMin ? clamp((d - dMin) / (dMax - dMin), 0.0, 1.0) : 0.0, rho / H);
    return 0.5 / size + x * (1.0 - 1.0 / size);
}

// A direction at radius r with cosine μ meets the ground sphere (Bruneton 2017, RayIntersectsGround).
bool rayMeetsGround(float r, float mu, float ground) {
    return mu < 0.0 && (r <= ground || (ground - r) * (ground + r) + r * r * mu * mu >= 0.0);
}

// The sun's transmittance through the atmosphere from planet-centred p toward unit `toSun`, from the LUT
// `lut` of `size` texels: 0 where the planet hides the sun, 1 above the top (for the effects lit by the sun
// through the atmosphere: the fogs' samples, the clouds').
vec3 sunTransmittanceFromLut(sampler2D lut, vec3 p, vec3 toSun, float ground, float top, vec2 size) {
    float r = length(p);
    float mu = dot(p, toSun) / r;
    if (rayMeetsGround(r, mu, ground)) return vec3(0.0);
    if (r >= top) return vec3(1.0);
    return textureLod(lut, transmittanceLutUv(r, mu, ground, top, size), 0.0).rgb;
}

#endif
