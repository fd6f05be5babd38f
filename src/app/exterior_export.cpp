// exterior_export.cpp - the census's exterior written to a file (exterior_export.h).
#include "app/exterior_export.h"

#include <algorithm>
#include <stdexcept>

#include "app/cli.h"
#include "scene/cad/step_exterior.h"
#include "scene/exterior.h"
#include "scene/gltf/gltf_writer.h"

namespace app {

void checkExteriorExport(const std::string& path, const scene::Scene& scene,
                         const std::string& source) {
    if (!path.ends_with(".glb") && !censusExportsStep(path))
        throw std::runtime_error(path + ": the exterior is written to .glb, .step or .stp");
    if (censusExportsStep(path) && !scene.brep)
        throw std::runtime_error(path + ": a STEP export needs a CAD model (STEP, IGES or BREP); " +
                                 source + " is a mesh: export to .glb instead");
}

ExteriorWritten writeExterior(const std::string& path, const scene::Scene& scene,
                              const scene::Census& census, const std::string& sourcePath,
                              scene::Healing healing) {
    if (censusExportsStep(path)) {
        const std::vector<uint8_t> keep = scene::seenObjects(scene, census);
        scene::writeStepSubset(sourcePath, scene, keep, path, healing);
        ExteriorWritten written;
        for (size_t o = 0; o < keep.size(); ++o) {
            if (!keep[o]) continue;
            ++written.objects;
            written.parts += scene.geometries[scene.objects[o].geometry].partCount;
        }
        return written;
    }
    const scene::PartSet seen = scene::seenParts(census);
    if (seen.empty()) throw std::runtime_error(path + ": nothing to write: the census saw no part");
    const scene::Scene kept = scene::keptParts(scene, seen);
    scene::writeGlb(kept, path);
    return {kept.uniquePartCount(), uint32_t(kept.objects.size())};
}

} // namespace app
