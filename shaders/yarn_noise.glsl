// core/model/yarn_noise.h/.cpp in GLSL, with the same 32-bit integer hash, so a yarn's colour
// variation is the one core computes.
uint hash32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

float noiseGradient(uint lattice, uint key) { return float(hash32(lattice ^ key) >> 8) * (1.0 / 8388608.0) - 1.0; }

float yarnNoise(float along, uint seed) {
    uint key = hash32(seed + 0x9e3779b9u);
    float x = along + float(key >> 8) * (1.0 / 16777216.0);
    float cell = floor(x);
    float f = x - cell;
    uint i = uint(int(cell));
    float fade = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    float a = noiseGradient(i, key) * f, b = noiseGradient(i + 1u, key) * (f - 1.0);
    return 2.0 * (a + fade * (b - a));
}
