#include "integrators.h"

#include "bdpt_integrator.h"
#include "integrator.h"
#include "path_integrator.h"

namespace woven {

namespace {

template <class I>
std::unique_ptr<Integrator> make(const RenderScene& scene, const CameraModel& camera, int maxDepth, bool filterWeave) {
    return std::make_unique<I>(scene, camera, maxDepth, filterWeave);
}

const std::vector<IntegratorKind> kIntegrators = {
    {"path", "unidirectional path tracing with next-event estimation", &make<PathIntegrator>},
    {"bdpt", "bidirectional path tracing, every connection strategy", &make<BdptIntegrator>},
    {"auto", "the more efficient of the others in a short pilot of each", nullptr},
};

const std::string kChosenPrefix = std::string(kIntegrators[2].name) + ": ";

}  // namespace

const std::vector<IntegratorKind>& integratorKinds() { return kIntegrators; }

const IntegratorKind* findIntegrator(const std::string& name) {
    for (const IntegratorKind& kind : kIntegrators)
        if (name == kind.name) return &kind;
    return nullptr;
}

const IntegratorKind& pathIntegrator() { return kIntegrators[0]; }
const IntegratorKind& autoIntegrator() { return kIntegrators[2]; }

std::vector<std::string> integratorNames() {
    std::vector<std::string> names;
    for (const IntegratorKind& kind : kIntegrators) names.push_back(kind.name);
    return names;
}

std::string integratorChoices(const char* quote) {
    std::string choices;
    for (size_t i = 0; i < kIntegrators.size(); ++i)
        choices += (i == 0 ? "" : i + 1 == kIntegrators.size() ? " or " : ", ") + std::string(quote) +
                   kIntegrators[i].name + quote;
    return choices;
}

std::string integratorRecord(const std::string& requested, const std::string& used) {
    const bool chosen = requested == autoIntegrator().name && used != autoIntegrator().name;
    return (chosen ? kChosenPrefix : "") + used;
}

bool isIntegratorRecord(const std::string& record) {
    if (findIntegrator(record)) return true;
    if (record.rfind(kChosenPrefix, 0) != 0) return false;
    const IntegratorKind* chosen = findIntegrator(record.substr(kChosenPrefix.size()));
    return chosen && chosen->make;
}

bool chosenByAuto(const std::string& record) { return record.rfind(autoIntegrator().name, 0) == 0; }

}  // namespace woven
