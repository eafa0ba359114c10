#include "thin_film.h"

#include <algorithm>
#include <cmath>

#include "math_constants.h"

namespace woven {

namespace {
float square(float x) { return x * x; }
float schlick(float f0, float cosTheta) { return f0 + (1.0f - f0) * std::pow(std::clamp(1.0f - cosTheta, 0.0f, 1.0f), 5.0f); }
float iorToF0(float transmitted, float incident) { return square((transmitted - incident) / (transmitted + incident)); }

// The CIE XYZ sensitivities' Fourier transform at an optical path difference (nm) and phase
// shift, fitted by Gaussians (Belcour and Barla's evalSensitivity), in linear Rec. 709.
glm::vec3 sensitivity(float opd, const glm::vec3& shift) {
    const float phase = 2.0f * kPi * opd * 1e-9f;
    const glm::vec3 val(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    const glm::vec3 pos(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    const glm::vec3 var(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    glm::vec3 xyz;
    for (int i = 0; i < 3; ++i)
        xyz[i] = val[i] * std::sqrt(2.0f * kPi * var[i]) * std::cos(pos[i] * phase + shift[i]) * std::exp(-square(phase) * var[i]);
    xyz.x += 9.7470e-14f * std::sqrt(2.0f * kPi * 4.5282e+09f) * std::cos(2.2399e+06f * phase + shift[0]) *
             std::exp(-4.5282e+09f * square(phase));
    xyz /= 1.0685e-7f;
    const glm::mat3 xyzToRec709(3.2404542f, -0.9692660f, 0.0556434f, -1.5371385f, 1.8760108f, -0.2040259f,
                                -0.4985314f, 0.0415560f, 1.0572252f);
    return xyzToRec709 * xyz;
}
}  // namespace

glm::vec3 thinFilmFresnel(float outsideIor, float filmIor, float cosTheta, float thicknessNm, const glm::vec3& baseF0) {
    // The film fades into the outside medium as it thins to nothing, so that a zero thickness
    // leaves the base's own Fresnel (the extension's reference does the same).
    const float t = std::clamp(thicknessNm / 0.03f, 0.0f, 1.0f);
    const float ior = outsideIor + (filmIor - outsideIor) * t * t * (3.0f - 2.0f * t);
    const float cos2Sq = 1.0f - square(outsideIor / ior) * (1.0f - square(cosTheta));
    if (cos2Sq < 0.0f) return glm::vec3(1.0f);
    const float cos2 = std::sqrt(cos2Sq);

    // Outside to film.
    const float r12 = schlick(iorToF0(ior, outsideIor), cosTheta);
    const float t121 = 1.0f - r12;
    const float phi21 = ior < outsideIor ? 0.0f : kPi;
    // Film to base, the base's index from its F0 (exact for dielectrics, an extinction-free
    // approximation for metals).
    glm::vec3 r23(0.0f), phi(0.0f);  // every channel set below; initialised for GCC's maybe-uninitialized
    for (int i = 0; i < 3; ++i) {
        const float s = std::sqrt(std::clamp(baseF0[i], 0.0f, 0.9999f));
        const float baseIor = (1.0f + s) / (1.0f - s);
        r23[i] = schlick(iorToF0(baseIor, ior), cos2);
        phi[i] = phi21 + (baseIor < ior ? kPi : 0.0f);
    }
    const float opd = 2.0f * ior * thicknessNm * cos2;

    const glm::vec3 r123 = glm::clamp(r12 * r23, glm::vec3(1e-5f), glm::vec3(0.9999f));
    const glm::vec3 rs = square(t121) * r23 / (1.0f - r123);
    glm::vec3 reflectance = r12 + rs;
    glm::vec3 cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= glm::sqrt(r123);
        reflectance += cm * 2.0f * sensitivity(float(m) * opd, float(m) * phi);
    }
    return glm::max(reflectance, glm::vec3(0.0f));
}

}  // namespace woven
