#include "fabric_fit.h"

#include "fitter.h"

namespace woven {

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
