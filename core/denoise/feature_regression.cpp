#include "feature_regression.h"

#include <algorithm>
#include <cmath>

#include "vector_clones.h"

namespace woven {

namespace {

constexpr int kR = FeatureRegression::kRegressors, kSize = kR + 1;  // the regressors and the constant
constexpr int kWeight = 0, kFirst = 1, kSecond = kFirst + kR, kColour = kSecond + kR * (kR + 1) / 2, kCross = kColour + 3;

constexpr int secondMoment(int j, int k) {  // j <= k
    return kSecond + j * kR - j * (j - 1) / 2 + (k - j);
}

}  // namespace

FeatureRegression::Sums::Sums(size_t pixels) {
    for (auto& m : moment) m.assign(pixels, 0.0f);
    moment[kWeight].assign(pixels, 1.0f);  // the centre, whose differences are 0
}

bool FeatureRegression::applies(const DenoiseBuffers& b) {
    for (const glm::vec3& d : b.direct)
        if (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f) return true;
    return false;
}

FeatureRegression::FeatureRegression(const DenoiseBuffers& b, const Demodulated& d, int pad)
    : regressors_(b.width, b.height, kR, pad, [&](size_t i, int c) {
          return b.usable(i) ? b.direct[i][c] / d.divisor.c[size_t(c)][i] : 0.0f;
      }),
      variance_(b.pixels(), glm::vec3(0.0f)) {
    if (b.directVariance.empty()) return;
    for (size_t i = 0; i < b.pixels(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float divisor = d.divisor.c[size_t(c)][i];
            variance_[i][c] = b.usable(i) ? b.directVariance[i][c] / (divisor * divisor) : 0.0f;
        }
}

WOVEN_VECTOR_CLONES void FeatureRegression::accumulate(size_t p, ptrdiff_t offset, int count, const float* weight,
                                                       const float* const* u, Sums& sums, size_t a) const {
    static_assert(kR == 3, "the loop below is written out for three regressors");
    const float* x0 = regressors_.plane(0) + p;
    const float* x1 = regressors_.plane(1) + p;
    const float* x2 = regressors_.plane(2) + p;
    const float *u0 = u[0], *u1 = u[1], *u2 = u[2];
    float* m[kMoments];
    for (int k = 0; k < kMoments; ++k) m[k] = &sums.moment[size_t(k)][a];
    // One pass over the row, every moment at once and written out: the differences stay in
    // registers, and each moment is loaded and stored once. Separate loops per moment took twice
    // the time, and the same sums as loops over j and k inside this one 1.4x (bench_denoise).
    // The moments' planes, the inputs and the weights are distinct arrays.
#if !defined(__clang__)  // GCC builds woven; clang (the fuzz build) would warn of the unknown pragma
#pragma GCC ivdep
#endif
    for (int i = 0; i < count; ++i) {
        const float w = weight[i];
        const float d0 = x0[i + offset] - x0[i], d1 = x1[i + offset] - x1[i], d2 = x2[i + offset] - x2[i];
        const float e0 = u0[i + offset] - u0[i], e1 = u1[i + offset] - u1[i], e2 = u2[i + offset] - u2[i];
        const float w0 = w * d0, w1 = w * d1, w2 = w * d2;
        m[kWeight][i] += w;
        m[kFirst + 0][i] += w0;
        m[kFirst + 1][i] += w1;
        m[kFirst + 2][i] += w2;
        m[secondMoment(0, 0)][i] += w0 * d0;
        m[secondMoment(0, 1)][i] += w0 * d1;
        m[secondMoment(0, 2)][i] += w0 * d2;
        m[secondMoment(1, 1)][i] += w1 * d1;
        m[secondMoment(1, 2)][i] += w1 * d2;
        m[secondMoment(2, 2)][i] += w2 * d2;
        m[kColour + 0][i] += w * e0;
        m[kColour + 1][i] += w * e1;
        m[kColour + 2][i] += w * e2;
        m[kCross + 0][i] += w0 * e0;
        m[kCross + 1][i] += w0 * e1;
        m[kCross + 2][i] += w0 * e2;
        m[kCross + 3][i] += w1 * e0;
        m[kCross + 4][i] += w1 * e1;
        m[kCross + 5][i] += w1 * e2;
        m[kCross + 6][i] += w2 * e0;
        m[kCross + 7][i] += w2 * e1;
        m[kCross + 8][i] += w2 * e2;
    }
}

FeatureRegression::Fit FeatureRegression::solve(const Sums& sums, size_t a, size_t pixel, float ridge) const {
    const auto m = [&](int index) { return double(sums.moment[size_t(index)][a]); };
    double A[kSize][kSize], B[kSize][4];  // B's last column: e_0, for [A^-1]_00
    A[0][0] = m(kWeight);
    for (int j = 0; j < kR; ++j) {
        A[0][j + 1] = A[j + 1][0] = m(kFirst + j);
        for (int k = j; k < kR; ++k) A[j + 1][k + 1] = A[k + 1][j + 1] = m(secondMoment(j, k));
    }
    for (int c = 0; c < 3; ++c) {
        B[0][c] = m(kColour + c);
        for (int j = 0; j < kR; ++j) B[j + 1][c] = m(kCross + 3 * j + c);
    }
    for (int j = 0; j < kSize; ++j) B[j][3] = j == 0 ? 1.0 : 0.0;
    for (int j = 1; j < kSize; ++j) {
        if (A[j][j] > 0.0) {
            A[j][j] *= 1.0 + double(ridge);
            continue;
        }
        // A regressor the same across the window: left out (its coefficient 0).
        for (int k = 0; k < kSize; ++k) A[j][k] = A[k][j] = 0.0;
        A[j][j] = 1.0;
        for (int c = 0; c < 3; ++c) B[j][c] = 0.0;
    }
    // Cholesky, A = L L^T, in place in A's lower triangle.
    for (int j = 0; j < kSize; ++j) {
        for (int k = 0; k < j; ++k) A[j][j] -= A[j][k] * A[j][k];
        if (!(A[j][j] > 0.0)) return {};  // not positive definite: the pixel as it is
        A[j][j] = std::sqrt(A[j][j]);
        for (int i = j + 1; i < kSize; ++i) {
            for (int k = 0; k < j; ++k) A[i][j] -= A[i][k] * A[j][k];
            A[i][j] /= A[j][j];
        }
    }
    for (int c = 0; c < 4; ++c) {
        for (int i = 0; i < kSize; ++i) {  // L y = b
            for (int k = 0; k < i; ++k) B[i][c] -= A[i][k] * B[k][c];
            B[i][c] /= A[i][i];
        }
        for (int i = kSize - 1; i >= 0; --i) {  // L^T x = y
            for (int k = i + 1; k < kSize; ++k) B[i][c] -= A[k][i] * B[k][c];
            B[i][c] /= A[i][i];
        }
    }
    // The point the fit is evaluated at, relative to the pixel's own regressors: towards the
    // window's weighted mean by the share of the pixel's that is noise.
    double at[kSize] = {1.0};
    for (int j = 0; j < kR; ++j) {
        const double w = m(kWeight), mean = m(kFirst + j) / w, spread = m(secondMoment(j, j)) / w - mean * mean;
        const double noise = double(variance_[pixel][j]);
        at[j + 1] = spread > 0.0 ? std::min(1.0, noise / spread) * mean : 0.0;
    }
    Fit fit;
    fit.leverage = 0.0f;
    for (int j = 0; j < kSize; ++j) {
        for (int c = 0; c < 3; ++c) fit.change[c] += float(at[j] * B[j][c]);
        fit.leverage += float(at[j] * B[j][3]);
    }
    return fit;
}

}  // namespace woven
