#include "fabric_fit.h"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <tuple>

#include "image_stats.h"
#include "linear_colours.h"
#include "photo_model.h"
#include "power_spectrum.h"
#include "thread_frequencies.h"
#include "tile_fold.h"
#include "transmitted_colours.h"
#include "weave_candidates.h"
#include "weave_lattice.h"
#include "yarn_transmission.h"

namespace woven {

namespace {

using Clock = std::chrono::steady_clock;

// How far from a thread direction the photo's peak may lie: a swatch laid a few degrees off the
// camera's axes still finds its threads, while a twill's or satin's off-axis peaks (14 degrees
// and more from the axes at the thread counts of real cloth) are left alone.
constexpr double kPeakHalfAngle = 4.0 * M_PI / 180.0;
// The least turn of a photo's threads the fit's renders follow: under it the threads drift by
// less than a tenth of a thread across the round trips' 27 (0.12), and the peaks' directions are
// measured to about that. Followed, the 0.02 to 0.06 degrees measured on the unturned plain round
// trip moved its warp's fitted red from 4.7 % to 18 % off at a lower loss (0.0074 for 0.0077):
// those colours are loose in the loss, and any change of the renders moves them.
constexpr double kLeastTurn = 0.25 * M_PI / 180.0;
// Colour mixtures per shortlisted weave (stage 2), which cost no rendering: enough for BOBYQA to
// converge on six colours (2n + 1 = 13 set up its model), as the weave whose colours are only
// half fitted can score worse than a wrong one.
constexpr int kColourEvaluations = 200;
// Full renders each shortlisted weave's gloss, widths and bump are refined with before the weaves
// are compared (stage 2): BOBYQA's 2n + 1 = 25 to set up its model of the 12 parameters and as
// many steps. A weave and its complement only tell apart once the yarns' widths and gloss are
// near: with the defaults' the synthetic 3/1 twill's colour mixtures preferred its complement.
constexpr int kShortlistRefineRenders = 50;
// Fixed-point steps of a free exposure where the photo clips (evaluate()): each leaves of the
// exposure's error the share of the block means that clipped pixels hold, so 4 leave 6 % of it
// where that share is a half (the rig's satin at exposure 1.6 clips half its pixels).
constexpr int kClippedExposureSteps = 4;
// Stage 4 restarts BOBYQA while a run lowers the loss by more than this fraction.
constexpr double kRestartGain = 1e-3;
// Closed-form colour solves at each point of stage 4: the fold's phase and shift come from the
// colours before the solve, so a second solve from the first's colours lays the folds right.
constexpr int kColourSolves = 2;
// Stage 5's samples a pixel, as a multiple of the fit's (polishColours()): its five images of a
// shot (for a flash and a backlit shot) at 4 times the samples cost about 20 of stage 4's, 8 % of
// the round trips' 250.
constexpr int kPolishSamples = 4;
// A photo's pixel clips where a channel reaches this share of its saturation (8 bits: 255).
constexpr float kClipped = 0.999f;

double angleDegrees(const glm::dvec2& a, const glm::dvec2& b) {
    // Peaks are defined up to sign (the spectrum of a real image is symmetric).
    const double c = std::abs(glm::dot(a, b)) / (glm::length(a) * glm::length(b));
    return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

// A fit parameter as NLopt sees it: x in [0, 1], mapped linearly or in log10 onto [lo, hi].
struct Axis {
    double lo, hi;
    bool log;
    double value(double x) const { return log ? std::pow(10.0, lo + x * (hi - lo)) : lo + x * (hi - lo); }
    double unit(double v) const {
        const double u = log ? (std::log10(std::max(v, 1e-30)) - lo) / (hi - lo) : (v - lo) / (hi - lo);
        return std::clamp(u, 0.0, 1.0);
    }
    double clamped(double v) const { return value(unit(v)); }  // v held within the axis
};

// Stage 4's parameters: weft and warp colour, rs, ex and ey (the warp's following the weft's:
// one photo under one light cannot tell them apart), both widths and cy.
constexpr int kColourAxes = 6;
constexpr size_t kRsAxis = kColourAxes;  // the shape's axes follow: ex, ey, the widths, cy
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

// p made the best fit so far: its loss, and each shot's terms and render.
void keepFit(FitResult& best, const WovenParams& p, double exposure, double loss, const std::vector<LossTerms>& terms,
             std::vector<Image> images) {
    best.params = p;
    best.exposure = exposure;
    best.loss = loss;
    best.shots.resize(terms.size());
    for (size_t i = 0; i < terms.size(); ++i) {
        best.shots[i].terms = terms[i];
        best.shots[i].render = std::move(images[i]);
    }
}

using Objective = std::function<double(const std::vector<double>&)>;

double trampoline(const std::vector<double>& x, std::vector<double>&, void* data) {
    return (*static_cast<const Objective*>(data))(x);
}

class Fitter {
public:
    Fitter(const std::vector<Shot>& shots, const FitOptions& options, const std::atomic<bool>& cancel,
           const std::function<void(const FitProgress&)>& onProgress)
        : shots_(shots), options_(options), cancel_(cancel), onProgress_(onProgress), start_(Clock::now()) {
        result_.shots.resize(shots_.size());
        result_.loss = INFINITY;
        for (const Shot& s : shots_) {
            anyFree_ = anyFree_ || !s.photo.exposure;
            whiteLight_ = whiteLight_ && litWhiteAndTargetOnly(s);
        }
        // The colours are the reflection's: every shot lit from the camera's side shows them. A
        // fit of backlit shots alone takes them from those, as if they were reflections.
        bool anyReflected = false;
        for (const Shot& s : shots_) anyReflected = anyReflected || !s.backlit;
        for (const Shot& s : shots_) reflected_.push_back(!s.backlit || !anyReflected);
        for (size_t i = 0; i < shots_.size(); ++i) allReflectedFree_ = allReflectedFree_ && (!reflected_[i] || !shots_[i].photo.exposure);
        transmitted_ = anyReflected && std::find(reflected_.begin(), reflected_.end(), false) != reflected_.end();
    }

    FitResult run() {
        WovenParams p = shots_[0].scene->materials[size_t(shots_[0].materials.at(0))].woven.value_or(WovenParams{});
        p.tile.clear();  // the fit tries (i, j, k) weaves
        p.warp_colors.clear();
        p.weft_colors.clear();
        p.warp_ex = p.ex;
        p.warp_ey = p.ey;

        const float shotRs = p.rs;
        stage_ = "thread counts";
        p.repeat = measurePhotos(p.repeat);
        p = initialColours(p);
        const bool weaveDone = chooseWeave(p);
        bool calibrated = false;
        if (weaveDone && !stop()) {
            stage_ = "thread counts";
            p = result_.params;
            calibrated = calibrateThreadCounts(p);
        }
        int refined = 0;
        if (calibrated && !stop()) refined = refine(shotRs);
        polishColours();
        measureThreads();
        compareWithLambertianPlanes();
        result_.complete = weaveDone && calibrated && refined >= 2 * int(shapeAxes().size()) + 1 && !cancel_;
        return std::move(result_);
    }

    // The loss of one material, the photos measured as run() measures them.
    FitResult lossOf(const WovenParams& p) {
        measurePhotos(p.repeat);
        evaluate(p);
        return std::move(result_);
    }

private:
    // Stage 1, the photos' statistics, and the shots the fit renders, each turned as its photo's
    // threads lie (a swatch laid a little askew). Returns the thread counts.
    glm::vec2 measurePhotos(glm::vec2 repeat) {
        repeat = threadCountsFromPhotos(repeat);
        for (size_t i = 0; i < shots_.size(); ++i) {
            std::vector<glm::dvec2> threads;
            if (photoPeaks_[i].ends) threads.push_back(photoPeaks_[i].ends->frequency);
            if (photoPeaks_[i].picks) threads.push_back(photoPeaks_[i].picks->frequency);
            threadFrequencies_.push_back(threads);
            photoStats_.push_back(imageStats(shots_[i].image, threads));
            photoGrids_.push_back(photoGrid(i));
            const double turn = threadTurn(photoPeaks_[i], shots_[i].uvPerPixel);
            renderShots_.push_back(turnedShot(shots_[i], std::abs(turn) >= kLeastTurn ? turn : 0.0));
        }
        measureBacklitPhotos();
        return repeat;
    }

    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    // The time budget is spent when what is left would only pay for polishColours(): its renders
    // of a shot at kPolishSamples times the samples, at the mean time one has taken so far.
    bool stop() const {
        const double t = elapsed();
        const double polish = shotRenders_ > 0 ? renderSeconds_ / shotRenders_ * kPolishSamples * polishShotRenders() : 0.0;
        return cancel_.load() || t + polish >= options_.seconds ||
               (options_.renders > 0 && result_.evaluations >= options_.renders);
    }

    void progress() {
        if (!onProgress_) return;
        FitProgress p;
        p.stage = stage_;
        p.evaluations = result_.evaluations;
        p.elapsed = elapsed();
        p.budget = options_.seconds;
        p.bestLoss = result_.loss;
        onProgress_(p);
    }

    // Each shot `which` names (all where it is empty); the others' images are left empty.
    std::vector<Image> render(const WovenParams& p, const std::vector<bool>& which = {}) {
        std::vector<Image> images(shots_.size());
        for (size_t i = 0; i < shots_.size(); ++i) {
            if ((!which.empty() && !which[i]) || (backlitLeftOut_ && !reflected_[i])) continue;
            const Clock::time_point start = Clock::now();
            images[i] = renderShot(renderShots_[i], p, options_.render, cancel_);
            renderSeconds_ += std::chrono::duration<double>(Clock::now() - start).count();
            ++shotRenders_;
            applyVignette(images[i], shots_[i].photo.vignetteSigmaPx);
        }
        ++result_.evaluations;
        return images;
    }

    // The exposure shared by the free shots that `images` holds (renders, vignetted, before
    // exposure): the least-squares scale of their block means, from the reflected shots where
    // any is free (a backlit shot's brightness is the transmission's to match). 1 where none is.
    double freeExposure(const std::vector<Image>& images) const {
        bool anyReflectedFree = false;
        for (size_t i = 0; i < shots_.size(); ++i)
            anyReflectedFree = anyReflectedFree || (!shots_[i].photo.exposure && reflected_[i] && !images[i].pixels.empty());
        const auto counted = [&](size_t i) {
            return !shots_[i].photo.exposure && !images[i].pixels.empty() && (reflected_[i] || !anyReflectedFree);
        };
        std::vector<float> photoMeans, renderMeans;
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (!counted(i)) continue;
            const std::vector<float>& pm = photoStats_[i].values[kStatBlockMeans];
            photoMeans.insert(photoMeans.end(), pm.begin(), pm.end());
            const std::vector<float> rm = blockMeans(images[i]);
            renderMeans.insert(renderMeans.end(), rm.begin(), rm.end());
        }
        if (photoMeans.empty()) return 1.0;
        double free = bestExposure(photoMeans, renderMeans);
        // Where a free shot's photo clips its highlights, the exposure whose render, clipped
        // alike, has the photo's block means: a few steps of that fixed point, each raising the
        // exposure by what the clipping took away.
        bool clips = false;
        for (size_t i = 0; i < shots_.size(); ++i) clips = clips || (counted(i) && std::isfinite(photoSaturation(shots_[i].photo)));
        for (int step = 0; clips && step < kClippedExposureSteps; ++step) {
            std::vector<float> clipped;
            for (size_t i = 0; i < shots_.size(); ++i) {
                if (!counted(i)) continue;
                Image exposed = images[i];
                expose(exposed, float(free), photoSaturation(shots_[i].photo));
                const std::vector<float> m = blockMeans(exposed);
                clipped.insert(clipped.end(), m.begin(), m.end());
            }
            free *= bestExposure(photoMeans, clipped);
        }
        return free;
    }

    // The loss of renders (vignetted, before exposure); with `record`, kept if the best so far. A
    // shot whose image is empty is left out (only a loss that is not recorded may leave one out,
    // and stage 2's, which all leave the backlit shots out).
    double evaluate(const WovenParams& p, std::vector<Image> images, bool record) {
        const double free = freeExposure(images);
        double total = 0.0;
        std::vector<LossTerms> terms(shots_.size());
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (images[i].pixels.empty()) continue;
            expose(images[i], float(shots_[i].photo.exposure.value_or(float(free))), photoSaturation(shots_[i].photo));
            std::optional<ThreadGrid> grid = renderGrid(p, i);
            if (grid) foldPhoto(i, grid->period);
            terms[i] = loss(photoStats_[i], imageStats(images[i], threadFrequencies_[i], grid ? &*grid : nullptr));
            total += terms[i].total;
        }

        if (record) {
            if (total < result_.loss) keepFit(result_, p, free, total, terms, std::move(images));
            result_.history.emplace_back(elapsed(), result_.loss);
            progress();
        }
        return total;
    }

    // A render that Ctrl-C cut short holds fewer samples than the others: it is not compared.
    double evaluate(const WovenParams& p) {
        std::vector<Image> images = render(p);
        return cancel_.load() ? INFINITY : evaluate(p, std::move(images), true);
    }

    // Where the photo's threads are: its peaks, signed as U and V grow (the sign of one against
    // the other is a twill's direction). None where the photo shows either direction no peak.
    std::optional<ThreadGrid> photoGrid(size_t i) const {
        const ThreadPeaks& peaks = photoPeaks_[i];
        if (!peaks.ends || !peaks.picks) return std::nullopt;
        const glm::dmat2& uvPerPixel = shots_[i].uvPerPixel;
        const glm::dvec2 gradU = gradientU(uvPerPixel), gradV = gradientV(uvPerPixel);
        ThreadGrid g;
        g.ends = glm::dot(peaks.ends->frequency, gradU) < 0.0 ? -peaks.ends->frequency : peaks.ends->frequency;
        g.picks = glm::dot(peaks.picks->frequency, gradV) < 0.0 ? -peaks.picks->frequency : peaks.picks->frequency;
        return g;
    }

    // Where a render of p puts its threads: the material's threads per UV unit through the
    // shot's camera, exactly, so its fold needs no peak of the render's noisy spectrum.
    std::optional<ThreadGrid> renderGrid(const WovenParams& p, size_t i) const {
        if (!photoGrids_[i]) return std::nullopt;
        const glm::dmat2& uvPerPixel = renderShots_[i].uvPerPixel;
        ThreadGrid g;
        g.ends = double(p.repeat.x) * gradientU(uvPerPixel);
        g.picks = double(p.repeat.y) * gradientV(uvPerPixel);
        g.period = p.pattern.x + p.pattern.y;
        return g;
    }

    // The photo's tile fold on the repeat of the weave being tried.
    void foldPhoto(size_t i, int period) {
        if (photoStats_[i].fold.side == 0 || photoGrids_[i]->period != period) {
            photoGrids_[i]->period = period;
            photoStats_[i].fold = foldTile(shots_[i].image, *photoGrids_[i]);
        }
    }

    // Stage 1: each direction's peak in the first shot that shows one.
    glm::vec2 threadCountsFromPhotos(glm::vec2 repeat) {
        bool ends = false, picks = false;
        for (size_t i = 0; i < shots_.size(); ++i) {
            const Shot& s = shots_[i];
            const ThreadPeaks peaks = threadPeaks(s.image, s.uvPerPixel, kPeakHalfAngle);
            const glm::dvec2 gradU = gradientU(s.uvPerPixel), gradV = gradientV(s.uvPerPixel);
            if (peaks.ends) result_.shots[i].photoFrequency.x = glm::length(peaks.ends->frequency);
            if (peaks.picks) result_.shots[i].photoFrequency.y = glm::length(peaks.picks->frequency);
            photoPeaks_.push_back(peaks);
            if (!ends && peaks.ends) {
                repeat.x = float(glm::length(peaks.ends->frequency) / glm::length(gradU));
                ends = true;
            }
            if (!picks && peaks.picks) {
                repeat.y = float(glm::length(peaks.picks->frequency) / glm::length(gradV));
                picks = true;
            }
        }
        if (!ends || !picks)
            result_.warnings.push_back(std::string("no photo shows the threads ") + (!ends ? "across u (warp ends)" : "") +
                                       (!ends && !picks ? " or " : "") + (!picks ? "across v (weft picks)" : "") +
                                       " as a peak of its spectrum: the thread count there stays the shot's material's (" +
                                       std::to_string(!ends ? repeat.x : repeat.y) +
                                       " per UV unit); a sharper or closer photo resolves them");
        return repeat;
    }

    // Grey yarns scaled so the first shot's mean colour is the photo's.
    WovenParams initialColours(WovenParams p) {
        p.weft_color = p.warp_color = glm::vec3(0.5f);
        const std::vector<Image> images = render(p);
        const size_t first = size_t(std::find(reflected_.begin(), reflected_.end(), true) - reflected_.begin());
        glm::dvec3 photo(0.0), rendered(0.0);
        for (const glm::vec3& v : shots_[first].image.pixels) photo += glm::dvec3(v);
        for (const glm::vec3& v : images[first].pixels) rendered += glm::dvec3(v);
        const double e = shots_[first].photo.exposure.value_or(1.0f);
        for (int c = 0; c < 3; ++c)
            p.weft_color[c] = float(std::clamp(0.5 * photo[c] / std::max(e * rendered[c], 1e-9), 0.02, 0.9));
        p.warp_color = p.weft_color;
        evaluate(p, images, true);
        return p;
    }


    // Each backlit shot's six parts (TransmissionStats' order) at p's shape, t = 1, vignetted:
    // each region's render at a transmittance of 1 (transmitted_colours.h), from which a backlit
    // render at any colours, t and g is a sum (backlitRender()). Under white light one render
    // per part holds the three regions, a channel each: a weft (0.5, 1, 0.5) and a warp
    // (1, 0.5, 0.5) pass T = (1/8, 0, 1/8) and (0, 1/8, 1/8) (a channel at R_d = 1 passes
    // nothing), so red is the weft alone, green the warp alone and blue all three. Otherwise
    // three per part: one yarn grey (T = 1/2) and the other white, then both grey.
    using TransmissionParts = std::vector<std::array<Image, 2 * kTransmittedRegionCount>>;
    TransmissionParts transmissionParts(WovenParams p) {
        std::vector<bool> backlit(shots_.size());
        for (size_t i = 0; i < shots_.size(); ++i) backlit[i] = !reflected_[i];
        p.transmission = 1.0f;
        TransmissionParts parts(shots_.size());
        for (int part = 0; part < 2; ++part) {
            p.transmission_gloss = float(part);
            // Per shot: the weft alone, the warp alone and all three regions, at transmittance tau.
            std::vector<std::array<Image, 3>> regions(shots_.size());
            double tau = 0.0;
            if (whiteLight_) {
                p.weft_color = {0.5f, 1.0f, 0.5f};
                p.warp_color = {1.0f, 0.5f, 0.5f};
                tau = double(yarnTransmittance(p.weft_color, 1.0f).r);
                const std::vector<Image> images = render(p, backlit);
                for (size_t s = 0; s < shots_.size(); ++s)
                    for (int r = 0; r < 3; ++r) {
                        regions[s][size_t(r)] = images[s];
                        for (glm::vec3& v : regions[s][size_t(r)].pixels) v = glm::vec3(v[r]);
                    }
            } else {
                const glm::vec3 grey(0.5f), white(1.0f);
                tau = double(yarnTransmittance(grey, 1.0f).r);
                const std::array<std::pair<glm::vec3, glm::vec3>, 3> colourings{
                    {{grey, white}, {white, grey}, {grey, grey}}};
                for (int r = 0; r < 3; ++r) {
                    std::tie(p.weft_color, p.warp_color) = colourings[size_t(r)];
                    const std::vector<Image> images = render(p, backlit);
                    for (size_t s = 0; s < shots_.size(); ++s) regions[s][size_t(r)] = images[s];
                }
            }
            for (size_t s = 0; s < shots_.size(); ++s) {
                if (!backlit[s]) continue;
                std::array<Image, 3>& r = regions[s];
                for (size_t i = 0; i < r[2].pixels.size(); ++i) {
                    r[0].pixels[i] /= float(tau);
                    r[1].pixels[i] /= float(tau);
                    r[2].pixels[i] = r[2].pixels[i] / float(tau) - r[0].pixels[i] - r[1].pixels[i];
                }
                for (int k = 0; k < kTransmittedRegionCount; ++k)
                    parts[s][size_t(part * kTransmittedRegionCount + k)] = std::move(r[size_t(k)]);
            }
        }
        return parts;
    }

    // The backlit shots' renders (vignetted, before exposure) at p's colours and transmission;
    // the other shots' are empty.
    std::vector<Image> backlitRenders(const TransmissionParts& parts, const WovenParams& p) const {
        const std::array<glm::dvec3, kTransmittedRegionCount> tau =
            regionTransmittances(glm::dvec3(p.weft_color), glm::dvec3(p.warp_color));
        const float kd = p.transmission * (1.0f - p.transmission_gloss), kg = p.transmission * p.transmission_gloss;
        std::vector<Image> images(shots_.size());
        for (size_t s = 0; s < shots_.size(); ++s) {
            if (reflected_[s]) continue;
            images[s] = parts[s][0];
            for (size_t i = 0; i < images[s].pixels.size(); ++i) {
                glm::vec3 v(0.0f);
                for (int r = 0; r < kTransmittedRegionCount; ++r)
                    v += glm::vec3(tau[size_t(r)]) * (kd * parts[s][size_t(r)].pixels[i] +
                                                      kg * parts[s][size_t(kTransmittedRegionCount + r)].pixels[i]);
                images[s].pixels[i] = v;
            }
        }
        return images;
    }

    // Each backlit shot's photo without the pixels it clips (withoutClipped()) and its statistics
    // the transmission's solves compare (transmitted_colours.h): the block means, and the tile fold
    // on the weave last tried (foldBacklitPhoto()). A render summed from parts cannot clip as the
    // photo did, and a lamp behind the cloth often clips where it shines through, so those pixels
    // are compared nowhere.
    struct BacklitPhoto {
        size_t shot = 0;
        std::vector<bool> clipped;  // per pixel
        Image image;
        ImageStats stats;
        int foldPeriod = 0;  // the weave's period stats.fold is folded on
        Image withoutClipped(Image other) const {
            for (size_t k = 0; k < other.pixels.size(); ++k)
                if (clipped[k]) other.pixels[k] = glm::vec3(0.0f);
            return other;
        }
    };
    void measureBacklitPhotos() {
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (reflected_[i]) continue;
            BacklitPhoto& b = backlitPhotos_.emplace_back();
            b.shot = i;
            const float saturation = photoSaturation(shots_[i].photo);
            for (const glm::vec3& v : shots_[i].image.pixels) b.clipped.push_back(std::max({v.r, v.g, v.b}) >= kClipped * saturation);
            b.image = b.withoutClipped(shots_[i].image);
            b.stats.values[kStatBlockMeans] = blockMeans(b.image);
        }
    }
    void foldBacklitPhoto(BacklitPhoto& b, int period) {
        if (b.foldPeriod == period) return;
        ThreadGrid grid = *photoGrids_[b.shot];
        grid.period = period;
        b.stats.fold = foldTile(b.image, grid);
        b.foldPeriod = period;
    }
    std::vector<const ImageStats*> backlitPhotoStats() const {
        std::vector<const ImageStats*> out;
        for (const BacklitPhoto& b : backlitPhotos_) out.push_back(&b.stats);
        return out;
    }

    // The backlit shots' parts, in backlitPhotos_'s order, without their photos' clipped pixels,
    // and their statistics: the block means, and with foldBacklitParts() the tile folds.
    struct BacklitParts {
        std::vector<std::array<Image, 2 * kTransmittedRegionCount>> images;
        std::vector<TransmissionStats> stats;
    };
    BacklitParts backlitParts(const TransmissionParts& parts) const {
        BacklitParts out;
        for (const BacklitPhoto& b : backlitPhotos_) {
            std::array<Image, 2 * kTransmittedRegionCount>& images = out.images.emplace_back();
            TransmissionStats& t = out.stats.emplace_back();
            for (size_t k = 0; k < images.size(); ++k) {
                images[k] = b.withoutClipped(parts[b.shot][k]);
                t.blockMeans[k] = blockMeans(images[k]);
            }
        }
        return out;
    }
    // The parts' tile folds, laid on their photos' at the phase of p's backlit render (its
    // transmission set), summed from `parts`.
    void foldBacklitParts(BacklitParts& out, const TransmissionParts& parts, const WovenParams& p) {
        const std::vector<Image> reference = backlitRenders(parts, p);
        for (size_t j = 0; j < backlitPhotos_.size(); ++j) {
            BacklitPhoto& b = backlitPhotos_[j];
            const std::optional<ThreadGrid> grid = renderGrid(p, b.shot);
            if (!grid) continue;
            foldBacklitPhoto(b, grid->period);
            std::vector<const Image*> images;
            for (const Image& part : out.images[j]) images.push_back(&part);
            const std::vector<TileFold> folds =
                foldsLaidOn(b.stats.fold, b.withoutClipped(reference[b.shot]), images, *grid);
            std::copy(folds.begin(), folds.end(), out.stats[j].folds.begin());
        }
    }

    // The backlit shots' exposures, in backlitPhotos_'s order: each given one, else
    // `shared` (none: the free one).
    std::vector<std::optional<double>> backlitExposures(std::optional<double> shared) const {
        std::vector<std::optional<double>> exposures;
        for (size_t i = 0; i < shots_.size(); ++i)
            if (!reflected_[i])
                exposures.push_back(shots_[i].photo.exposure ? std::optional<double>(*shots_[i].photo.exposure) : shared);
        return exposures;
    }

    // Stage 2: the weaves the photo's spectrum shortlists (weave_lattice.h), each with its
    // colours fitted, the best kept. False when the budget ran out first.
    // Where backlit shots join reflected ones, the weaves are fitted to the reflected shots
    // alone: the face's weave is what reflection shows, light through the cloth shows the gaps
    // between its yarns, which a weave and its complement share, and until the transmission is
    // solved at the weave's colours and shape (stage 4) the backlit shots' loss is 10 to 100
    // times the flash's: counted, it chose the rig's 3/1 twill's and 5-end satin's complements,
    // and its refinement drove the yarns' widths and gloss away from the flash's (docs/FIT.md).
    bool chooseWeave(const WovenParams& start) {
        const std::vector<glm::ivec3> candidates = shortlist();
        if (transmitted_) countBacklitShots(false);
        bool done = true;
        for (size_t c = 0; c < candidates.size(); ++c) {
            if (stop()) {
                result_.warnings.push_back("the time ran out during the weave search (" + std::to_string(c) + " of " +
                                           std::to_string(candidates.size()) + " weaves tried)");
                done = false;
                break;
            }
            stage_ = "weave " + std::to_string(c + 1) + "/" + std::to_string(candidates.size());
            WovenParams p = start;
            p.pattern = candidates[c];
            fitColours(p);
            // A lone weave is refined too where backlit shots join: each point of stage 4 then
            // costs three renders, and from the shot material's widths and gloss it ended where
            // the flash's loss was 7 times its truth's (the rig's plain weave, its weft 0.97
            // wide for 0.85).
            if (candidates.size() == 1 && !transmitted_) {
                evaluate(p);
                continue;
            }
            p = rescaled(p);
            std::vector<double> x = encode(p);
            const Objective objective = [&](const std::vector<double>& v) { return evaluate(decode(v, p)); };
            minimise(x, objective, kShortlistRefineRenders);
        }
        if (transmitted_) countBacklitShots(true);
        return done;
    }

    // The weaves whose lattice of peaks the first shot that shows both thread directions has;
    // every candidate where none does.
    std::vector<glm::ivec3> shortlist() const {
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (!photoGrids_[i]) continue;
            return weaveShortlist(rankWeavesBySpectrum(shots_[i].image, photoGrids_[i]->ends, photoGrids_[i]->picks));
        }
        std::vector<glm::ivec3> all;
        for (const WeaveCandidate& c : weaveCandidates()) all.push_back(c.pattern);
        return all;
    }

    // Each shot's K_weft, K_warp and R (linear_colours.h) at p's shape, vignetted: renders whose
    // mixtures are p's renders with any yarn colours, exactly, under direct light from point
    // lights. Under white light one render holds all three (the weft red and the warp green, so
    // that blue is R's alone, as the gloss is white); otherwise three: both yarns black, a white
    // weft, a white warp.
    using ColourBasis = std::vector<std::array<Image, 3>>;
    ColourBasis colourBasis(WovenParams p) {
        ColourBasis basis(shots_.size());
        if (whiteLight_) {
            p.weft_color = glm::vec3(1.0f, 0.0f, 0.0f);
            p.warp_color = glm::vec3(0.0f, 1.0f, 0.0f);
            const std::vector<Image> images = render(p, reflected_);
            for (size_t s = 0; s < shots_.size(); ++s) {
                basis[s] = {images[s], images[s], images[s]};
                for (size_t i = 0; i < images[s].pixels.size(); ++i) {
                    const glm::vec3 v = images[s].pixels[i];
                    basis[s][0].pixels[i] = glm::vec3(v.r - v.b);
                    basis[s][1].pixels[i] = glm::vec3(v.g - v.b);
                    basis[s][2].pixels[i] = glm::vec3(v.b);
                }
            }
            return basis;
        }
        p.weft_color = p.warp_color = glm::vec3(0.0f);
        const std::vector<Image> black = render(p, reflected_);
        p.weft_color = glm::vec3(1.0f);
        const std::vector<Image> weft = render(p, reflected_);
        p.weft_color = glm::vec3(0.0f);
        p.warp_color = glm::vec3(1.0f);
        const std::vector<Image> warp = render(p, reflected_);
        for (size_t s = 0; s < shots_.size(); ++s) {
            basis[s] = {weft[s], warp[s], black[s]};
            for (size_t i = 0; i < black[s].pixels.size(); ++i) {
                basis[s][0].pixels[i] -= black[s].pixels[i];
                basis[s][1].pixels[i] -= black[s].pixels[i];
            }
        }
        return basis;
    }

    // The renders of p's colours at the basis's shape, its gloss R scaled by `rsScale`.
    static std::vector<Image> mixture(const ColourBasis& basis, const WovenParams& p, float rsScale = 1.0f) {
        std::vector<Image> images;
        for (const std::array<Image, 3>& b : basis) {
            images.push_back(b[2]);
            for (size_t i = 0; i < b[2].pixels.size(); ++i)
                images.back().pixels[i] = rsScale * b[2].pixels[i] + (p.weft_color * b[0].pixels[i] + p.warp_color * b[1].pixels[i]);
        }
        return images;
    }

    // Where one render makes the colour basis: every light and the environment white (or grey),
    // and nothing in view but the target, so that no coloured surface adds to R.
    static bool litWhiteAndTargetOnly(const Shot& shot) {
        const SceneDescription& scene = *shot.scene;
        auto grey = [](const glm::vec3& c) { return c.r == c.g && c.g == c.b; };
        for (const PunctualLight& l : scene.lights)
            if (!grey(l.intensity)) return false;
        if (!grey(scene.environment.color) || scene.environment.image) return false;
        for (const Mesh& m : scene.meshes)
            if (std::find(shot.materials.begin(), shot.materials.end(), m.material) == shot.materials.end()) return false;
        return true;
    }

    // NLopt over mixtures of the colour basis, which cost no rendering.
    void fitColours(WovenParams& p) {
        const ColourBasis basis = colourBasis(p);
        const Objective objective = [&](const std::vector<double>& x) {
            const WovenParams q = decode(x, p);
            return evaluate(q, mixture(basis, q), false);
        };
        std::vector<double> x = encode(p);
        x.resize(kColourAxes);
        minimise(x, objective, kColourEvaluations);
        p = decode(x, p);
    }

    // Runs NLopt's BOBYQA from x within [0, 1]^n, at most `evaluations` (0: until the budget is
    // spent or it converges); x becomes the best point it met. Returns the evaluations it took.
    int minimise(std::vector<double>& x, const Objective& objective, int evaluations) {
        nlopt::opt opt(nlopt::LN_BOBYQA, unsigned(x.size()));
        opt.set_lower_bounds(std::vector<double>(x.size(), 0.0));
        opt.set_upper_bounds(std::vector<double>(x.size(), 1.0));
        int count = 0;
        std::vector<double> best = x;
        double bestValue = INFINITY;
        const Objective counted = [&](const std::vector<double>& v) {
            if (stop()) throw nlopt::forced_stop();
            ++count;
            const double f = objective(v);
            if (f < bestValue) {
                bestValue = f;
                best = v;
            }
            return f;
        };
        opt.set_min_objective(trampoline, const_cast<Objective*>(&counted));
        if (evaluations > 0) opt.set_maxeval(evaluations);
        opt.set_initial_step(0.08);
        opt.set_xtol_rel(1e-4);
        for (double& v : x) v = std::clamp(v, 0.0, 1.0);
        double f = 0.0;
        try {
            opt.optimize(x, f);
        } catch (const std::runtime_error&) {
            // forced_stop (the budget, Ctrl-C) or roundoff_limited: the best point so far stands.
        }
        if (std::isfinite(bestValue)) x = best;
        return count;
    }

    // Stage 3: the photo's peaks against the same peaks of a render of the chosen weave, measured
    // the same way, so what the window, the lens and the weave do to a peak cancels.
    bool calibrateThreadCounts(WovenParams& p) {
        for (int iteration = 0; iteration < 2; ++iteration) {
            if (stop()) return false;
            const std::vector<Image> images = render(p);
            const ThreadPeaks r = threadPeaks(images[0], renderShots_[0].uvPerPixel, kPeakHalfAngle);
            const ThreadPeaks& photo = photoPeaks_[0];
            if (photo.ends && r.ends) p.repeat.x *= float(glm::length(photo.ends->frequency) / glm::length(r.ends->frequency));
            if (photo.picks && r.picks)
                p.repeat.y *= float(glm::length(photo.picks->frequency) / glm::length(r.picks->frequency));
        }
        // Kept where their loss is lower: a render's peak can be pulled by the weave's own peaks
        // beside it (the synthetic 3/1 twill's ends' peak moved 3 % from the photo's after the
        // counts had been scaled to meet it, the counts 3 % off and the loss 5 times the truth's).
        evaluate(p);
        return true;
    }

    // A free exposure scales the render as the yarns' colours and rs do together, so the
    // optimiser drifts along that valley, and a colour that reaches its axis's end is held there
    // (the synthetic satin's warp ended at 0.002 for 0.1 with the exposure 4 times the truth's).
    // Where an exposure is free, the colours and rs scaled so the brightest channel is 0.5, the
    // middle of its axis, before each weave's refinement (stage 2); the loss stays what it was
    // (the exposure takes the scale back).
    WovenParams rescaled(WovenParams p) const {
        const float brightest = std::max({p.weft_color.r, p.weft_color.g, p.weft_color.b, p.warp_color.r,
                                          p.warp_color.g, p.warp_color.b});
        if (!anyFree_ || !(brightest > 0.0f)) return p;
        const float k = 0.5f / brightest;
        p.weft_color *= k;
        p.warp_color *= k;
        p.rs = float(fullAxes()[kRsAxis].clamped(double(p.rs * k)));
        return p;
    }

    // Where rs is solved with the colours, the exposure and the transmission under a free exposure
    // (solveColoursWithTransmission()): backlit shots join reflected ones, every reflected shot's
    // exposure is free (else rs is a product with the exposure in some shots only), and one render
    // makes the colour basis, so that its R is the gloss alone, which rs scales.
    bool rsSolvedWithColours() const { return transmitted_ && allReflectedFree_ && whiteLight_; }

    // Stage 4's axes of fullAxes(), searched by BOBYQA: the shape, as the colours are solved at
    // each point. rs too where no exposure is free; a free exposure scales the gloss as it does
    // the colours (a photo shows only exposure x rs), so rs is held there, or solved with the
    // colours where rsSolvedWithColours().
    std::vector<size_t> shapeAxes() const {
        std::vector<size_t> axes;
        for (size_t a = anyFree_ ? kRsAxis + 1 : kRsAxis; a < fullAxes().size(); ++a) axes.push_back(a);
        return axes;
    }

    // The loss of p's shape with the colours (and a free exposure) that match the photos' block
    // means and tile folds best (linear_colours.h); kept if the best so far. One colour basis,
    // kColourSolves solves, each folding the basis at the phase and shift of the last colours'
    // mixture.
    // Where backlit shots join reflected ones, the colours, the exposure and the transmission are
    // then solved against both together (transmitted_colours.h), from the reflected shots'
    // colours: the light through the yarns holds their hue without the gloss.
    double evaluateSolvingColours(WovenParams p) {
        const ColourBasis basis = colourBasis(p);
        if (cancel_.load()) return INFINITY;
        // Where only some exposures are free, the free one is held at its best so far: the
        // colours and the exposure are then a product only in the free shots.
        std::vector<std::optional<double>> exposures;
        std::vector<const ImageStats*> photos;
        std::vector<size_t> solved;  // the shots the colours are solved from
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (!reflected_[i]) continue;
            const Shot& s = shots_[i];
            exposures.push_back(s.photo.exposure ? std::optional<double>(*s.photo.exposure)
                                : allReflectedFree_ ? std::nullopt
                                                    : std::optional<double>(result_.exposure));
            photos.push_back(&photoStats_[i]);
            solved.push_back(i);
        }
        LinearColours colours;  // the last solve's
        colours.weft = glm::dvec3(p.weft_color);
        colours.warp = glm::dvec3(p.warp_color);
        colours.exposure = result_.exposure;
        // The solve with the backlit shots starts from the last solve's colours and from p's as it
        // came (the best fit's in stage 4), and lays every fold at p's colours as it came: the
        // reflected shots' solve is ill-conditioned where the gloss's pattern nears the yarns'
        // (the rig's satin at ey = 4 gave every colour above 1 and an exposure a third of its
        // neighbours'), and folds laid at such colours pair the wrong places.
        const WovenParams entry = p;
        const LinearColours entryColours = colours;
        std::vector<LinearStats> entryStats;
        std::vector<LinearStats> stats(solved.size());
        for (int solve = 0; solve < kColourSolves; ++solve) {
            const std::vector<Image> reference = mixture(basis, p);
            for (size_t j = 0; j < solved.size(); ++j) {
                const size_t i = solved[j];
                for (size_t k = 0; k < 3; ++k) stats[j].blockMeans[k] = blockMeans(basis[i][k]);
                const std::optional<ThreadGrid> grid = renderGrid(p, i);
                if (!grid) continue;
                foldPhoto(i, grid->period);
                const std::vector<TileFold> folds =
                    foldsLaidOn(photoStats_[i].fold, reference[i], {&basis[i][0], &basis[i][1], &basis[i][2]}, *grid);
                std::copy(folds.begin(), folds.end(), stats[j].folds.begin());
            }
            if (solve == 0) entryStats = stats;
            const LinearColours c = solveColours(photos, stats, exposures);
            if (!c.valid) break;
            colours = c;
            const Axis& axis = fullAxes()[0];
            p.weft_color = glm::vec3(glm::clamp(c.weft, glm::dvec3(axis.lo), glm::dvec3(axis.hi)));
            p.warp_color = glm::vec3(glm::clamp(c.warp, glm::dvec3(axis.lo), glm::dvec3(axis.hi)));
        }
        std::vector<Image> images = mixture(basis, p);
        if (transmitted_ && !backlitLeftOut_) {
            const TransmissionParts parts = transmissionParts(p);
            if (cancel_.load()) return INFINITY;
            const ReflectedSolve reflected{photos, exposures, entryStats, colours, entryColours};
            const WovenParams scaled = withRsScaled(p, float(solveWithBacklitShots(p, entry, reflected, parts)));
            images = mixture(basis, p, scaled.rs / p.rs);
            const std::vector<Image> transmitted = backlitRenders(parts, p);
            for (size_t i = 0; i < shots_.size(); ++i)
                if (!reflected_[i]) images[i] = transmitted[i];
            p = scaled;
        }
        return evaluate(p, std::move(images), true);
    }

    // What evaluateSolvingColours() solved the colours from: the reflected shots' photos and
    // exposures, their statistics with the folds laid at the entry's colours, the last solve's
    // colours and the entry's.
    struct ReflectedSolve {
        std::vector<const ImageStats*> photos;
        std::vector<std::optional<double>> exposures;
        std::vector<LinearStats> entryStats;
        LinearColours last, entry;
    };

    // p's colours, free exposure and transmission solved against the reflected and the backlit
    // shots together (transmitted_colours.h), from the reflected solve's colours and from
    // `entry`'s (p as evaluateSolvingColours() was given it), every fold laid at `entry`'s.
    // Returns the factor on rs solved with them (1 where rsSolvedWithColours() is false).
    double solveWithBacklitShots(WovenParams& p, const WovenParams& entry, const ReflectedSolve& reflected,
                               const TransmissionParts& parts) {
        // The backlit folds' reference: the entry, with the transmission solved at its colours.
        const std::optional<double> shared = allReflectedFree_ ? std::nullopt : std::optional<double>(result_.exposure);
        const std::vector<std::optional<double>> backlitExposed = backlitExposures(shared);
        std::vector<double> exposures;
        for (const std::optional<double>& e : backlitExposed) exposures.push_back(e.value_or(reflected.entry.exposure));
        BacklitParts backlit = backlitParts(parts);
        const TransmissionSplit first = solveTransmission(backlitPhotoStats(), backlit.stats, exposures,
                                                          reflected.entry.weft, reflected.entry.warp);
        WovenParams reference = entry;
        reference.transmission = float(first.transmission());
        reference.transmission_gloss = float(first.gloss());
        foldBacklitParts(backlit, parts, reference);
        LinearColours entryStart = reflected.entry;
        if (!allReflectedFree_) entryStart.exposure = 1.0;
        const TransmittedColours joint =
            solveColoursWithTransmission(reflected.photos, reflected.entryStats, reflected.exposures, backlitPhotoStats(),
                                         backlit.stats, backlitExposed, {reflected.last, entryStart},
                                         rsSolvedWithColours());
        p.weft_color = glm::vec3(joint.colours.weft);
        p.warp_color = glm::vec3(joint.colours.warp);
        p.transmission = float(joint.split.transmission());
        p.transmission_gloss = float(joint.split.gloss());
        return joint.rsScale;
    }

    // p, its colours and transmission solved at its rs, with rs scaled by `k` (within its axis) and
    // the colours and the transmission rescaled so that p renders nearly as it did with its R
    // scaled by as much. The diffuse reflection carries a factor 1 - rs (../shared/MODEL.md 4),
    // kept exactly, and so does the light through the yarns (docs/MODEL_TRANSMISSION.md), kept but
    // for its factor 1 - R_d (1 to 2 % at the factors of 1.1 to 1.3 the round trips solve). R
    // itself is rs's but for Schlick's (1 - rs)(1 - h.k)^5, small for a flash beside the lens.
    static WovenParams withRsScaled(WovenParams p, float k) {
        if (k == 1.0f || !(p.rs > 0.0f)) return p;
        const float rs = float(fullAxes()[kRsAxis].clamped(double(p.rs * k))), keep = (1.0f - p.rs) / (1.0f - rs);
        p.weft_color = glm::min(p.weft_color * keep, glm::vec3(1.0f));
        p.warp_color = glm::min(p.warp_color * keep, glm::vec3(1.0f));
        p.transmission = std::min(p.transmission * keep, 1.0f);
        p.rs = rs;
        return p;
    }

    // Stage 4: BOBYQA over the shape from the best so far, the colours (and the transmission,
    // where backlit shots join reflected ones) solved at each point, again from where it stopped
    // while that gains (it stops where its trust region shrinks, often short of the minimum),
    // until the budget is spent. `shotRs`: the shot material's rs, held where an exposure is
    // free, unless rsSolvedWithColours(). Returns the points it tried.
    int refine(float shotRs) {
        stage_ = transmitted_ ? "gloss, widths, bump, transmission" : "gloss, widths, bump";
        const std::vector<size_t> axes = shapeAxes();
        int points = 0;
        for (double before = INFINITY; result_.loss < before * (1.0 - kRestartGain) && !stop();) {
            before = result_.loss;
            WovenParams base = result_.params;
            if (anyFree_ && !rsSolvedWithColours()) base.rs = shotRs;
            const std::vector<double> full = encode(base);
            std::vector<double> x;
            for (size_t a : axes) x.push_back(full[a]);
            const Objective objective = [&](const std::vector<double>& v) {
                std::vector<double> y = full;
                for (size_t k = 0; k < axes.size(); ++k) y[axes[k]] = v[k];
                return evaluateSolvingColours(decode(y, base));
            };
            points += minimise(x, objective, 0);
        }
        return points;
    }

    // Stage 5: the best fit rendered again at kPolishSamples times the samples, and with its
    // colours (and transmission) solved once more from renders at those samples, the better of
    // the two kept. Stage 4's best point is the one whose renders' noise lowered its loss the
    // most, and its colours were solved from that noise (docs/FIT.md: over the pair at
    // five render seeds it took the mean of the worst colour channel from 4.4 to 4.1 %, and from
    // 7.4 to 6.6 % with rs held). Both are compared at the new samples, as a render's noise
    // counts in the spectrum; the loss that stands is theirs.
    void polishColours() {
        if (!std::isfinite(result_.loss) || cancel_.load()) return;
        FitResult before = result_;
        const int samples = options_.render.spp;
        options_.render.spp = samples * kPolishSamples;
        result_.loss = INFINITY;
        stage_ = "colours";
        evaluate(before.params);
        if (!cancel_.load()) evaluateSolvingColours(before.params);
        options_.render.spp = samples;
        if (cancel_.load() || !std::isfinite(result_.loss)) result_ = std::move(before);
    }
    // The renders of a shot polishColours() makes: the best fit's of every shot, then stage 4's
    // at one point (the reflected shots' colour basis and the backlit shots' parts).
    int polishShotRenders() const {
        const int backlit = int(std::count(reflected_.begin(), reflected_.end(), false));
        const int reflected = int(shots_.size()) - backlit;
        return int(shots_.size()) + reflected * (whiteLight_ ? 1 : 3) + backlit * (whiteLight_ ? 2 : 6);
    }

    // Stage 2 fits to the reflected shots alone (backlitLeftOut_), the best so far then compared
    // by their loss alone. Switching re-evaluates it under the loss that follows, the colours
    // (and where the backlit shots count, the transmission) solved as stage 4 solves them.
    void countBacklitShots(bool counted) {
        backlitLeftOut_ = !counted;
        if (!std::isfinite(result_.loss) || cancel_.load()) return;
        const WovenParams best = result_.params;
        result_.loss = INFINITY;
        evaluateSolvingColours(best);
    }

    void compareWithLambertianPlanes() {
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (shots_[i].backlit || cancel_.load()) continue;
            Image plane = renderShotLambertian(shots_[i], options_.render, cancel_);
            applyVignette(plane, shots_[i].photo.vignetteSigmaPx);
            const std::vector<float> rendered = blockMeans(plane);
            const std::vector<float>& photo = photoStats_[i].values[kStatBlockMeans];
            glm::dvec3 pr(0.0), rr(0.0);
            for (size_t k = 0; k < photo.size(); ++k) {
                pr[int(k % 3)] += double(photo[k]) * rendered[k];
                rr[int(k % 3)] += double(rendered[k]) * rendered[k];
            }
            const glm::dvec3 scale = pr / glm::max(rr, glm::dvec3(1e-300));
            std::vector<float> scaled(rendered.size());
            for (size_t k = 0; k < scaled.size(); ++k) scaled[k] = float(scale[int(k % 3)] * rendered[k]);
            result_.shots[i].lambertianBlockMeansError = colourError(photo, scaled, 1);
        }
    }

    void measureThreads() {
        for (size_t i = 0; i < shots_.size() && i < photoPeaks_.size(); ++i) {
            ShotFit& f = result_.shots[i];
            if (f.render.pixels.empty()) continue;
            const ThreadPeaks r = threadPeaks(f.render, renderShots_[i].uvPerPixel, kPeakHalfAngle);
            const ThreadPeaks& p = photoPeaks_[i];
            if (r.ends) f.renderFrequency.x = glm::length(r.ends->frequency);
            if (r.picks) f.renderFrequency.y = glm::length(r.picks->frequency);
            if (r.ends && p.ends) f.directionError.x = angleDegrees(r.ends->frequency, p.ends->frequency);
            if (r.picks && p.picks) f.directionError.y = angleDegrees(r.picks->frequency, p.picks->frequency);
        }
    }

    const std::vector<Shot>& shots_;
    // What the fit renders: each shot with its cloth turned as the photo shows it (measurePhotos()).
    std::vector<Shot> renderShots_;
    FitOptions options_;
    const std::atomic<bool>& cancel_;
    std::function<void(const FitProgress&)> onProgress_;
    Clock::time_point start_;
    std::vector<ImageStats> photoStats_;
    std::vector<ThreadPeaks> photoPeaks_;
    std::vector<std::vector<glm::dvec2>> threadFrequencies_;  // per shot, where its thread peaks are read
    std::vector<std::optional<ThreadGrid>> photoGrids_;        // per shot, where its tile fold is read
    std::string stage_;
    FitResult result_;
    bool anyFree_ = false;  // of the shots' exposures
    bool allReflectedFree_ = true;  // of the reflected_ shots' exposures
    bool whiteLight_ = true;                 // every shot makes its colour basis in one render
    // Per shot: the colours are fitted to it (not backlit, or every shot is).
    std::vector<bool> reflected_;
    bool transmitted_ = false;  // backlit shots beside reflected ones: the transmission is solved
    // Renders leave the backlit shots out (stage 2).
    bool backlitLeftOut_ = false;
    std::vector<BacklitPhoto> backlitPhotos_;  // where transmitted_
    double renderSeconds_ = 0.0;  // spent in renderShot()
    int shotRenders_ = 0;         // renders of a shot
};

}  // namespace

FitResult fitFabric(const std::vector<Shot>& shots, const FitOptions& options, const std::atomic<bool>& cancel,
                    const std::function<void(const FitProgress&)>& onProgress) {
    if (shots.empty()) throw FitError("woven fit: no shots");
    return Fitter(shots, options, cancel, onProgress).run();
}

FitResult fitLoss(const std::vector<Shot>& shots, const WovenParams& params, const FitOptions& options) {
    if (shots.empty()) throw FitError("woven fit: no shots");
    const std::atomic<bool> cancel{false};
    return Fitter(shots, options, cancel, {}).lossOf(params);
}

}  // namespace woven
