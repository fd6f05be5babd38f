// cad_assembly.h - a split STEP file's scene, put together in the parent of a parallel load
// from the skeleton's leaves (the assembly tree, placements, names) and the pieces' answers
// (meshed solids), in any order they come: every object exists with its final unique part IDs
// as soon as the skeleton is read (the pieces' layouts number the parts), and draws once its
// piece is in. The finished scene is the same whatever order the pieces came in, and names,
// places and colours its objects as a whole-file read of the file would (cad_read.h's
// splitSolids and cad_build.h's addObjects). Plain scene data and Open CASCADE-free, but for
// the B-rep bytes it keeps.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/cad/cad_jobs.h"
#include "scene/step/step_split.h"

namespace scene::cad {

class CadAssembly {
  public:
    // Throws Bad where the skeleton does not stand for the file: a leaf whose shape is no
    // piece's set yet has faces (then the file is read whole instead).
    CadAssembly(const SkeletonAnswer& skeleton, const std::vector<step::Piece>& pieces,
                const std::string& stem);

    // kRelativeDeflection of the diagonal of the leaves' boxes, placed.
    double automaticDeflection() const;
    // Whether some leaf draws the piece (the others need not be read), and how many objects do.
    bool used(uint32_t piece) const { return !objectsOf_[piece].empty(); }
    uint32_t objectsOf(uint32_t piece) const { return uint32_t(objectsOf_[piece].size()); }

    // A piece's answer put in place. Throws Bad where it does not match its layout.
    void add(const PieceAnswer& answer);
    // A piece that will not come: its objects stay, drawing nothing, named in a warning.
    void lose(uint32_t piece, const std::string& why);

    // What is there now, for a viewer to draw while the rest loads.
    CadPartial partial() const;
    uint64_t bytesDone() const { return bytesDone_; }

    // The scene in the order a whole-file read would build it (geometries by first use,
    // materials by first use, the arrays in geometry order), with levels of detail chosen among
    // the pieces' candidates where `levels` asks, the B-rep kept encoded, and the load's
    // warnings and counts. The assembly is spent.
    CadLoadResult finish(uint32_t levels);

  private:
    void addLeaf(const SkeletonLeaf& leaf, const step::Piece& piece, int32_t index);
    uint32_t geometryFor(uint32_t piece, uint32_t object, const std::string& name, uint32_t faces);
    uint32_t materialOf(const std::string& name, const glm::vec4& color);
    void canonicalize();

    Scene scene_;
    std::string stem_;
    std::vector<step::Piece> pieces_;
    std::vector<std::vector<uint32_t>> objectsOf_;  // by piece: the scene's objects drawing it
    std::vector<std::vector<uint32_t>> geometryOf_; // by piece, by layout object: the geometry
    std::vector<glm::dmat4> leafWorld_;             // by scene object: its leaf's placement
    std::vector<uint32_t> objectLayout_;            // by scene object: its layout object
    std::vector<std::optional<glm::dvec4>> instanceColor_; // by scene object
    std::vector<Bounds> boxes_;                            // by scene object, in the world
    std::vector<uint8_t> state_;                           // by scene object
    std::vector<std::string> brep_;                        // by geometry: encodeShape's bytes
    std::vector<GeometryCandidates> candidates_;           // by the scene's geometry numbers
    std::map<std::string, uint32_t> materialByName_;
    std::vector<std::string> warnings_;
    std::vector<std::string> lost_; // "<product> (N solids): why"
    uint32_t faceless_ = 0, unnamedCompounds_ = 0, unnamedSolids_ = 0, unnamedShapes_ = 0;
    uint32_t faces_ = 0, facesFailed_ = 0, emptyShapes_ = 0;
    uint64_t bytesDone_ = 0;
    uint32_t entities_ = 0, failedEntities_ = 0, faceEntities_ = 0; // what the readers dropped
};

} // namespace scene::cad
