#include "piecewise_constant.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
std::vector<float> rowIntegrals(const std::vector<float>& func, int nu, int nv) {
    std::vector<float> rows(nv);
    for (int v = 0; v < nv; ++v) {
        double sum = 0.0;
        for (int u = 0; u < nu; ++u) sum += func[size_t(v) * nu + u];
        rows[v] = float(sum / nu);
    }
    return rows;
}
}  // namespace

PiecewiseConstant1D::PiecewiseConstant1D(const std::vector<float>& func) : cdf_(func.size() + 1) {
    const int n = int(func.size());
    // Accumulate in double: environment maps have millions of pieces.
    std::vector<double> cdf(n + 1, 0.0);
    for (int i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + double(std::max(func[i], 0.0f)) / n;
    const double sum = cdf[n];
    integral_ = float(sum);
    for (int i = 0; i <= n; ++i) cdf_[i] = sum > 0.0 ? float(cdf[i] / sum) : float(i) / float(n);
    cdf_[n] = 1.0f;
}

namespace {
// The largest i with cdf[i] <= u, among pieces 0 .. n-1.
int findPiece(const std::vector<float>& cdf, float u) {
    const auto it = std::upper_bound(cdf.begin(), cdf.end() - 1, u);
    return std::clamp(int(it - cdf.begin()) - 1, 0, int(cdf.size()) - 2);
}
}  // namespace

float PiecewiseConstant1D::sampleContinuous(float u, float* pdf, int* offset) const {
    int i = findPiece(cdf_, u);
    // Skip zero-width pieces that u can land on exactly at their boundary.
    while (cdf_[i + 1] - cdf_[i] <= 0.0f && i + 1 < size()) ++i;
    if (offset) *offset = i;
    const float width = cdf_[i + 1] - cdf_[i];
    float du = width > 0.0f ? (u - cdf_[i]) / width : 0.5f;
    du = std::clamp(du, 0.0f, std::nextafter(1.0f, 0.0f));
    if (pdf) *pdf = width * size();
    return std::min((float(i) + du) / float(size()), std::nextafter(1.0f, 0.0f));
}

int PiecewiseConstant1D::sampleDiscrete(float u, float* pmf, float* uRemapped) const {
    int i = findPiece(cdf_, u);
    while (cdf_[i + 1] - cdf_[i] <= 0.0f && i + 1 < size()) ++i;
    const float width = cdf_[i + 1] - cdf_[i];
    if (pmf) *pmf = width;
    if (uRemapped) *uRemapped = width > 0.0f ? std::clamp((u - cdf_[i]) / width, 0.0f, std::nextafter(1.0f, 0.0f)) : 0.0f;
    return i;
}

float PiecewiseConstant1D::discretePmf(int index) const { return cdf_[index + 1] - cdf_[index]; }

float PiecewiseConstant1D::pdf(float x) const {
    const int i = int(std::fmin(std::fmax(x * size(), 0.0f), float(size() - 1)));  // NaN -> 0
    return discretePmf(i) * size();
}

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<float>& func, int nu, int nv)
    : marginal_(rowIntegrals(func, nu, nv)) {
    conditional_.reserve(nv);
    for (int v = 0; v < nv; ++v)
        conditional_.emplace_back(std::vector<float>(func.begin() + size_t(v) * nu, func.begin() + size_t(v + 1) * nu));
}

glm::vec2 PiecewiseConstant2D::sample(const glm::vec2& u, float* pdf) const {
    float pdfV, pdfU;
    int row;
    const float v = marginal_.sampleContinuous(u.y, &pdfV, &row);
    const float x = conditional_[row].sampleContinuous(u.x, &pdfU);
    *pdf = pdfV * pdfU;
    return {x, v};
}

float PiecewiseConstant2D::pdf(const glm::vec2& p) const {
    const int row = int(std::fmin(std::fmax(p.y * marginal_.size(), 0.0f), float(marginal_.size() - 1)));
    return marginal_.pdf(p.y) * conditional_[row].pdf(p.x);
}

}  // namespace woven
