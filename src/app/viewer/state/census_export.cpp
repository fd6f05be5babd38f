// census_export.cpp - Export seen... on its worker (census_export.h).
#include "app/viewer/state/census_export.h"

#include <filesystem>

namespace app {

namespace fs = std::filesystem;

std::string ExportOutcome::line() const {
    if (!written) return error;
    return std::string(replaced ? "replaced " : "wrote ") + path + ": " +
           std::to_string(written->parts) + " parts, " + std::to_string(written->objects) +
           (solids ? " solids" : " objects");
}

std::string defaultExportPath(const LoadedScene& loaded) {
    const std::string& builtin = loaded.settings.builtin;
    std::error_code error;
    fs::path folder = fs::current_path(error);
    std::string stem = builtin.substr(0, builtin.find(':')); // "procedural:preset=small"
    if (builtin.empty()) {
        const fs::path model(loaded.source);
        if (model.has_parent_path()) folder = model.parent_path();
        stem = model.stem().string();
    }
    return (folder / (stem + "-exterior.glb")).string();
}

void CensusExport::start(ExportJob job) {
    writing_ = true;
    line_ = "writing " + job.path + "...";
    worker_.submit([job = std::move(job)](const std::atomic<bool>&) {
        std::error_code error;
        ExportOutcome outcome{job.path, {}, fs::exists(job.path, error), {}};
        outcome.solids = job.scene->brep != nullptr;
        try {
            outcome.written =
                writeExterior(job.path, *job.scene, job.census, job.source, job.healing);
        } catch (const std::exception& e) {
            outcome.error = e.what();
        }
        return std::optional(std::move(outcome));
    });
}

ExportOutcome CensusExport::refuse(const std::string& path, const std::string& error) {
    ExportOutcome outcome{path, {}, false, error};
    line_ = outcome.line();
    return outcome;
}

std::optional<ExportOutcome> CensusExport::take() {
    std::optional<ExportOutcome> outcome = worker_.take();
    if (!outcome) return std::nullopt;
    writing_ = false;
    line_ = outcome->line();
    return outcome;
}

} // namespace app
