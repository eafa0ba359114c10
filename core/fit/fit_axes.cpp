#include "fit_axes.h"

#include <algorithm>
#include <cmath>

namespace woven {

double Axis::value(double x) const { return log ? std::pow(10.0, lo + x * (hi - lo)) : lo + x * (hi - lo); }

double Axis::unit(double v) const {
    const double u = log ? (std::log10(std::max(v, 1e-30)) - lo) / (hi - lo) : (v - lo) / (hi - lo);
    return std::clamp(u, 0.0, 1.0);
}

const std::vector<Axis>& fullAxes() {
    static const std::vector<Axis> axes{
        {0.002, 1.0, false}, {0.002, 1.0, false}, {0.002, 1.0, false},  // weft_color
        {0.002, 1.0, false}, {0.002, 1.0, false}, {0.002, 1.0, false},  // warp_color
        {-3.0, -0.3, true},                                             // rs: 0.001 to 0.5
        {0.0, 3.5, true},                                               // ex: 1 to 3000
        {-1.0, 2.0, true},                                              // ey: 0.1 to 100
        {0.3, 1.0, false}, {0.3, 1.0, false},                           // yarn_width, warp_width
        {0.0, 1.0, false},                                              // cy
    };
    return axes;
}

std::vector<double> encode(const WovenParams& p) {
    const std::vector<double> v{p.weft_color.r, p.weft_color.g, p.weft_color.b, p.warp_color.r, p.warp_color.g,
                                p.warp_color.b, p.rs,           p.ex,           p.ey,           p.yarn_width,
                                p.warp_width,   p.cy};
    std::vector<double> x(v.size());
    for (size_t i = 0; i < v.size(); ++i) x[i] = fullAxes()[i].unit(v[i]);
    return x;
}

WovenParams decode(const std::vector<double>& x, WovenParams p) {
    std::vector<double> v(x.size());
    for (size_t i = 0; i < x.size(); ++i) v[i] = fullAxes()[i].value(std::clamp(x[i], 0.0, 1.0));
    p.weft_color = glm::vec3(float(v[0]), float(v[1]), float(v[2]));
    p.warp_color = glm::vec3(float(v[3]), float(v[4]), float(v[5]));
    if (x.size() > kColourAxes) {
        p.rs = float(v[6]);
        p.ex = p.warp_ex = float(v[7]);
        p.ey = p.warp_ey = float(v[8]);
        p.yarn_width = float(v[9]);
        p.warp_width = float(v[10]);
        p.cy = float(v[11]);
    }
    return p;
}

}  // namespace woven
