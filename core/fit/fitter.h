#pragma once
// The fit's state across its stages (docs/FIT.md, "How it fits"): one Fitter per fitFabric() or
// fitLoss() call, holding the shots, the photos' statistics, the budget and the best fit so far.
// Its methods live by stage: fitter.cpp (rendering, the loss, the budget), fit_thread_counts.cpp
// (stages 1 and 3), fit_weave_search.cpp (stage 2), fit_shape_search.cpp (stages 4 and 5) and
// fit_backlit_shots.cpp (the backlit shots' parts, photos and solves).
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bobyqa.h"
#include "fabric_fit.h"
#include "fit_axes.h"
#include "image_stats.h"
#include "linear_colours.h"
#include "thread_frequencies.h"
#include "tile_fold.h"
#include "transmitted_colours.h"

namespace woven {

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
// Two shots' peaks are of the same threads where their frequencies differ by less than this
// share (twill1's backlit photo shows its cloth 1.15 times larger, docs/FIT.md).
constexpr double kSameThreads = 0.2;
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
// The longest budget taken as given (about 30 years); a longer --time is as good as endless, and
// its deadline would overflow the clock.
constexpr double kLongestBudget = 1e9;
// A photo's pixel clips where a channel reaches this share of its saturation (8 bits: 255).
constexpr float kClipped = 0.999f;

class Fitter {
public:
    Fitter(const std::vector<Shot>& shots, const FitOptions& options, const std::atomic<bool>& cancel,
           const std::function<void(const FitProgress&)>& onProgress)
        : shots_(shots), options_(options), cancel_(cancel), onProgress_(onProgress), start_(Clock::now()),
          deadline_(start_ + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(std::clamp(options.seconds, 0.0, kLongestBudget)))),
          renderDeadline_(deadline_) {
        options_.render.deadline = renderDeadline_;
        result_.shots.resize(shots_.size());
        result_.loss = INFINITY;
        for (const Shot& s : shots_) {
            anyExposureFree_ = anyExposureFree_ || !s.photo.exposure;
            oneRenderColourBasis_ = oneRenderColourBasis_ && litWhiteAndTargetOnly(s);
        }
        // The colours are the reflection's: every shot lit from the camera's side shows them. A
        // fit of backlit shots alone takes them from those, as if they were reflections.
        bool anyReflected = false;
        for (const Shot& s : shots_) anyReflected = anyReflected || !s.backlit;
        for (const Shot& s : shots_) fitsColours_.push_back(!s.backlit || !anyReflected);
        for (size_t i = 0; i < shots_.size(); ++i)
            everyColourShotFree_ = everyColourShotFree_ && (!fitsColours_[i] || !shots_[i].photo.exposure);
        solvesTransmission_ =
            anyReflected && std::find(fitsColours_.begin(), fitsColours_.end(), false) != fitsColours_.end();
    }
    FitResult run();
    // The loss of one material, the photos measured as run() measures them.
    FitResult lossOf(const WovenParams& p);

private:
    // Each backlit shot's six parts (TransmissionStats' order) at p's shape, t = 1, vignetted:
    // each region's render at a transmittance of 1 (transmitted_colours.h), from which a backlit
    // render at any colours, t and g is a sum (backlitRender()). Under white light one render
    // per part holds the three regions, a channel each: a weft (0.5, 1, 0.5) and a warp
    // (1, 0.5, 0.5) pass T = (1/8, 0, 1/8) and (0, 1/8, 1/8) (a channel at R_d = 1 passes
    // nothing), so red is the weft alone, green the warp alone and blue all three. Otherwise
    // three per part: one yarn grey (T = 1/2) and the other white, then both grey.
    using TransmissionParts = std::vector<std::array<Image, 2 * kTransmittedRegionCount>>;

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

    // The backlit shots' parts, in backlitPhotos_'s order, without their photos' clipped pixels,
    // and their statistics: the block means, and with foldBacklitParts() the tile folds.
    struct BacklitParts {
        std::vector<std::array<Image, 2 * kTransmittedRegionCount>> images;
        std::vector<TransmissionStats> stats;
    };

    // Each shot's K_weft, K_warp and R (linear_colours.h) at p's shape, vignetted: renders whose
    // mixtures are p's renders with any yarn colours, exactly, under direct light from point
    // lights. Under white light one render holds all three (the weft red and the warp green, so
    // that blue is R's alone, as the gloss is white); otherwise three: both yarns black, a white
    // weft, a white warp.
    using ColourBasis = std::vector<std::array<Image, 3>>;

    // What evaluateSolvingColours() solved the colours from: the reflected shots' photos and
    // exposures, their statistics with the folds laid at the entry's colours, the last solve's
    // colours and the entry's.
    struct ReflectedSolve {
        std::vector<const ImageStats*> photos;
        std::vector<std::optional<double>> exposures;
        std::vector<LinearStats> entryStats;
        LinearColours last, entry;
    };

    // Stage 1, the photos' statistics, and the shots the fit renders, each turned as its photo's
    // threads lie (a swatch laid a little askew). Returns the thread counts.
    glm::vec2 measurePhotos(glm::vec2 repeat);
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    // The search stops when what is left of the renders' time would only pay for polishColours()
    // (its renders at kPolishSamples times the samples, at the mean time a render of a shot has
    // taken so far), on Ctrl-C, or when the render budget is spent.
    bool stop() const;
    // Ctrl-C, or the renders' time is over: every render under way then stops after its pass and
    // comes back empty (FitRenderSettings::deadline), and what it was for is dropped.
    bool outOfTime() const { return cancel_.load() || Clock::now() >= renderDeadline_; }
    void progress();
    // Each shot `which` names (all where it is empty); the others' images are left empty. None
    // where a render was cut short (outOfTime()): what they were for is dropped.
    std::vector<Image> render(const WovenParams& p, const std::vector<bool>& which = {});
    // The exposure shared by the free shots that `images` holds (renders, vignetted, before
    // exposure): the least-squares scale of their block means, from the reflected shots where
    // any is free (a backlit shot's brightness is the transmission's to match). 1 where none is.
    double freeExposure(const std::vector<Image>& images) const;
    // The loss of renders (vignetted, before exposure); with `record`, kept if the best so far. A
    // shot whose image is empty is left out (only a loss that is not recorded may leave one out,
    // and stage 2's, which all leave the backlit shots out).
    double evaluate(const WovenParams& p, std::vector<Image> images, bool record);
    // A render that Ctrl-C cut short holds fewer samples than the others: it is not compared.
    double evaluate(const WovenParams& p);
    // Where the photo's threads are: its peaks, signed as U and V grow (the sign of one against
    // the other is a twill's direction). None where the photo shows either direction no peak.
    std::optional<ThreadGrid> photoGrid(size_t i) const;
    // Where a render of p puts its threads: the material's threads per UV unit through the
    // shot's camera, exactly, so its fold needs no peak of the render's noisy spectrum.
    std::optional<ThreadGrid> renderGrid(const WovenParams& p, size_t i) const;
    // The photo's tile fold on the repeat of the weave being tried.
    void foldPhoto(size_t i, int period);
    // Stage 1: each direction's peak in the first shot that shows one.
    glm::vec2 threadCountsFromPhotos(glm::vec2 repeat);
    // Stage 1's peaks unfolded where the first shot that shows both directions has a weave's
    // lattice only at the finer threads the pixel grid folds onto them (thread_fold.h), the
    // thread counts taken from those.
    glm::vec2 unfoldThreadCounts(glm::vec2 repeat);
    // Grey yarns scaled so the first shot's mean colour is the photo's.
    WovenParams initialColours(WovenParams p);
    TransmissionParts transmissionParts(WovenParams p);
    // The backlit shots' renders (vignetted, before exposure) at p's colours and transmission;
    // the other shots' are empty.
    std::vector<Image> backlitRenders(const TransmissionParts& parts, const WovenParams& p) const;
    void measureBacklitPhotos();
    void foldBacklitPhoto(BacklitPhoto& b, int period);
    std::vector<const ImageStats*> backlitPhotoStats() const;
    BacklitParts backlitParts(const TransmissionParts& parts) const;
    // The parts' tile folds, laid on their photos' at the phase of p's backlit render (its
    // transmission set), summed from `parts`.
    void foldBacklitParts(BacklitParts& out, const TransmissionParts& parts, const WovenParams& p);
    // The backlit shots' exposures, in backlitPhotos_'s order: each given one, else
    // `shared` (none: the free one).
    std::vector<std::optional<double>> backlitExposures(std::optional<double> shared) const;
    // Stage 2: the weaves the photo's spectrum shortlists (weave_lattice.h), each with its
    // colours fitted, the best kept. False when the budget ran out first.
    // Where backlit shots join reflected ones, the weaves are fitted to the reflected shots
    // alone: the face's weave is what reflection shows, light through the cloth shows the gaps
    // between its yarns, which a weave and its complement share, and until the transmission is
    // solved at the weave's colours and shape (stage 4) the backlit shots' loss is 10 to 100
    // times the flash's: counted, it chose the rig's 3/1 twill's and 5-end satin's complements,
    // and its refinement drove the yarns' widths and gloss away from the flash's (docs/FIT.md).
    bool chooseWeave(const WovenParams& start);
    // The weaves whose lattice of peaks the first shot that shows both thread directions has;
    // every candidate where none does.
    std::vector<glm::ivec3> shortlist() const;
    ColourBasis colourBasis(WovenParams p);
    // The renders of p's colours at the basis's shape, its gloss R scaled by `rsScale`.
    static std::vector<Image> mixture(const ColourBasis& basis, const WovenParams& p, float rsScale = 1.0f);
    // Where one render makes the colour basis: every light and the environment white (or grey),
    // and nothing in view but the target, so that no coloured surface adds to R.
    static bool litWhiteAndTargetOnly(const Shot& shot);
    // NLopt over mixtures of the colour basis, which cost no rendering.
    void fitColours(WovenParams& p);
    // minimiseInUnitBox() (bobyqa.h), stopped where the budget is spent.
    int minimise(std::vector<double>& x, const Objective& objective, int evaluations);
    // Stage 3: the photo's peaks against the same peaks of a render of the chosen weave, measured
    // the same way, so what the window, the lens and the weave do to a peak cancels.
    bool calibrateThreadCounts(WovenParams& p);
    // A free exposure scales the render as the yarns' colours and rs do together, so the
    // optimiser drifts along that valley, and a colour that reaches its axis's end is held there
    // (the synthetic satin's warp ended at 0.002 for 0.1 with the exposure 4 times the truth's).
    // Where an exposure is free, the colours and rs scaled so the brightest channel is 0.5, the
    // middle of its axis, before each weave's refinement (stage 2); the loss stays what it was
    // (the exposure takes the scale back).
    WovenParams rescaled(WovenParams p) const;
    // Where rs is solved with the colours, the exposure and the transmission under a free exposure
    // (solveColoursWithTransmission()): backlit shots join reflected ones, every reflected shot's
    // exposure is free (else rs is a product with the exposure in some shots only), and one render
    // makes the colour basis, so that its R is the gloss alone, which rs scales.
    bool rsSolvedWithColours() const { return solvesTransmission_ && everyColourShotFree_ && oneRenderColourBasis_; }
    // Stage 4's axes of fullAxes(), searched by BOBYQA: the shape, as the colours are solved at
    // each point. rs too where no exposure is free; a free exposure scales the gloss as it does
    // the colours (a photo shows only exposure x rs), so rs is held there, or solved with the
    // colours where rsSolvedWithColours().
    std::vector<size_t> shapeAxes() const;
    // The loss of p's shape with the colours (and a free exposure) that match the photos' block
    // means and tile folds best (linear_colours.h); kept if the best so far. One colour basis,
    // kColourSolves solves, each folding the basis at the phase and shift of the last colours'
    // mixture.
    // Where backlit shots join reflected ones, the colours, the exposure and the transmission are
    // then solved against both together (transmitted_colours.h), from the reflected shots'
    // colours: the light through the yarns holds their hue without the gloss.
    double evaluateSolvingColours(WovenParams p);
    // p's colours, free exposure and transmission solved against the reflected and the backlit
    // shots together (transmitted_colours.h), from the reflected solve's colours and from
    // `entry`'s (p as evaluateSolvingColours() was given it), every fold laid at `entry`'s.
    // Returns the factor on rs solved with them (1 where rsSolvedWithColours() is false).
    double solveWithBacklitShots(WovenParams& p, const WovenParams& entry, const ReflectedSolve& reflected,
                                 const TransmissionParts& parts);
    // p, its colours and transmission solved at its rs, with rs scaled by `k` (within its axis) and
    // the colours and the transmission rescaled so that p renders nearly as it did with its R
    // scaled by as much. The diffuse reflection carries a factor 1 - rs (../shared/MODEL.md 4),
    // kept exactly, and so does the light through the yarns (docs/MODEL_TRANSMISSION.md), kept but
    // for its factor 1 - R_d (1 to 2 % at the factors of 1.1 to 1.3 the round trips solve). R
    // itself is rs's but for Schlick's (1 - rs)(1 - h.k)^5, small for a flash beside the lens.
    static WovenParams withRsScaled(WovenParams p, float k);
    // Stage 4: BOBYQA over the shape from the best so far, the colours (and the transmission,
    // where backlit shots join reflected ones) solved at each point, again from where it stopped
    // while that gains (it stops where its trust region shrinks, often short of the minimum),
    // until the budget is spent. `shotRs`: the shot material's rs, held where an exposure is
    // free, unless rsSolvedWithColours(). Returns the points it tried.
    int refine(float shotRs);
    // Stage 5: the best fit rendered again at kPolishSamples times the samples, and with its
    // colours (and transmission) solved once more from renders at those samples, the better of
    // the two kept. Stage 4's best point is the one whose renders' noise lowered its loss the
    // most, and its colours were solved from that noise (docs/FIT.md: over the pair at
    // five render seeds it took the mean of the worst colour channel from 4.4 to 4.1 %, and from
    // 7.4 to 6.6 % with rs held). Both are compared at the new samples, as a render's noise
    // counts in the spectrum; the loss that stands is theirs.
    void polishColours();
    // The renders of a shot polishColours() makes: the best fit's of every shot, then stage 4's
    // at one point (the reflected shots' colour basis and the backlit shots' parts).
    int polishShotRenders() const;
    // Stage 2 fits to the reflected shots alone (rendersLeaveBacklitOut_), the best so far then
    // compared by their loss alone. Switching re-evaluates it under the loss that follows, the
    // colours (and where the backlit shots count, the transmission) solved as stage 4 solves them.
    void countBacklitShots(bool counted);
    // Each reflected shot's best Lambertian plane (ShotFit::lambertianBlockMeansError): it needs
    // the photos alone, so it is measured before the search, inside the budget.
    void compareWithLambertianPlanes();
    void measureThreads();

    const std::vector<Shot>& shots_;
    // What the fit renders: each shot with its cloth turned as the photo shows it (measurePhotos()).
    std::vector<Shot> renderShots_;
    FitOptions options_;
    const std::atomic<bool>& cancel_;
    std::function<void(const FitProgress&)> onProgress_;
    // The budget's end, and the renders': twice what stage 1 took before the budget's end, as
    // the last evaluation's statistics (their spectra) and measureThreads() (the last renders'
    // thread counts) each take about what stage 1 took on the photos.
    Clock::time_point start_, deadline_, renderDeadline_;
    std::vector<ImageStats> photoStats_;
    std::vector<ThreadPeaks> photoPeaks_;
    std::vector<std::vector<glm::dvec2>> threadFrequencies_;  // per shot, where its thread peaks are read
    std::vector<std::optional<ThreadGrid>> photoGrids_;        // per shot, where its tile fold is read
    std::string stage_;
    FitResult result_;
    bool anyExposureFree_ = false;
    // Per shot: the yarns' colours are fitted to it (it is lit from the camera's side, or every
    // shot is backlit).
    std::vector<bool> fitsColours_;
    bool everyColourShotFree_ = true;  // every fitsColours_ shot's exposure is free
    // Every shot makes its colour basis in one render (litWhiteAndTargetOnly()).
    bool oneRenderColourBasis_ = true;
    // Backlit shots beside ones that fit the colours: the transmission is solved from them.
    bool solvesTransmission_ = false;
    bool rendersLeaveBacklitOut_ = false;  // stage 2's renders
    std::vector<BacklitPhoto> backlitPhotos_;  // where solvesTransmission_
    double renderSeconds_ = 0.0;  // spent in renderShot()
    int shotRenders_ = 0;         // renders of a shot
    // Stage 1 found the ends (picks) folded by the pixel grid: photoPeaks_ hold them unfolded.
    bool unfoldedEnds_ = false, unfoldedPicks_ = false;
};

}  // namespace woven
