#pragma once
// `woven fit --report DIR` (docs/FIT.md): for every shot the photo beside the fitted material's
// render (shot_N.png), each statistic's error and the thread frequencies (report.txt), and the
// loss against time (loss.csv, drawn by gnuplot as loss.png where it is installed).
#include <string>
#include <vector>

#include "fabric_fit.h"
#include "shot.h"

namespace woven {

// Makes the folder `dir` and checks each file the report of `shots` shots writes there as an
// output (output_path.h): what `woven fit` does before it fits. Throws FileWriteError naming it.
void checkFitReport(const std::string& dir, size_t shots);

// Throws std::runtime_error naming the file it could not write. Returns the lines of warning it
// has (gnuplot missing).
std::vector<std::string> writeFitReport(const std::string& dir, const std::vector<Shot>& shots, const FitResult& result);

}  // namespace woven
