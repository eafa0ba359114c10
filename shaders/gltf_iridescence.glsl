// core/bsdf/thin_film.cpp's thinFilmFresnel() in GLSL: KHR_materials_iridescence's reflectance
// of a thin dielectric film over the base (Belcour and Barla 2017, as the extension approximates
// it), linear Rec. 709.
float thinFilmSchlick(float f0, float cosTheta) { return f0 + (1.0 - f0) * pow5(clamp(1.0 - cosTheta, 0.0, 1.0)); }
float thinFilmIorToF0(float transmitted, float incident) {
    float r = (transmitted - incident) / (transmitted + incident);
    return r * r;
}

// The CIE XYZ sensitivities' Fourier transform at an optical path difference (nm) and phase shift.
vec3 thinFilmSensitivity(float opd, vec3 shift) {
    float phase = 2.0 * PI * opd * 1e-9;
    const vec3 val = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 pos = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 var = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = val * sqrt(2.0 * PI * var) * cos(pos * phase + shift) * exp(-phase * phase * var);
    xyz.x += 9.7470e-14 * sqrt(2.0 * PI * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) * exp(-4.5282e+09 * phase * phase);
    xyz /= 1.0685e-7;
    const mat3 xyzToRec709 = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259,
                                  -0.4985314, 0.0415560, 1.0572252);
    return xyzToRec709 * xyz;
}

vec3 thinFilmFresnel(float outsideIor, float filmIor, float cosTheta, float thicknessNm, vec3 baseF0) {
    float ior = mix(outsideIor, filmIor, smoothstep(0.0, 0.03, thicknessNm));
    float cos2Sq = 1.0 - (outsideIor / ior) * (outsideIor / ior) * (1.0 - cosTheta * cosTheta);
    if (cos2Sq < 0.0) return vec3(1.0);
    float cos2 = sqrt(cos2Sq);
    float r12 = thinFilmSchlick(thinFilmIorToF0(ior, outsideIor), cosTheta);
    float t121 = 1.0 - r12;
    float phi21 = ior < outsideIor ? 0.0 : PI;
    vec3 s = sqrt(clamp(baseF0, 0.0, 0.9999));
    vec3 baseIor = (1.0 + s) / (1.0 - s);
    vec3 r23, phi;
    for (int i = 0; i < 3; ++i) {
        r23[i] = thinFilmSchlick(thinFilmIorToF0(baseIor[i], ior), cos2);
        phi[i] = phi21 + (baseIor[i] < ior ? PI : 0.0);
    }
    float opd = 2.0 * ior * thicknessNm * cos2;
    vec3 r123 = clamp(r12 * r23, vec3(1e-5), vec3(0.9999));
    vec3 rs = t121 * t121 * r23 / (1.0 - r123);
    vec3 reflectance = r12 + rs;
    vec3 cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= sqrt(r123);
        reflectance += cm * 2.0 * thinFilmSensitivity(float(m) * opd, float(m) * phi);
    }
    return max(reflectance, vec3(0.0));
}
