// step_types.h - what the splitter needs to know of each entity type, worked out once per
// interned type (step_index.h) rather than once per record.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/step/step_index.h"

namespace scene::step {

enum TypeFlag : uint32_t {
    kSolid = 1u << 0,        // MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS, FACETED_BREP
    kSurfaceModel = 1u << 1, // SHELL_BASED_SURFACE_MODEL, FACE_BASED_SURFACE_MODEL
    kShell = 1u << 2,        // what leads from a solid or a surface model to its faces
    kFace = 1u << 3,         // ADVANCED_FACE, FACE_SURFACE
    kOrientedFace = 1u << 4, // counts as the face it wraps
    kVertexPoint = 1u << 5,
    kCartesianPoint = 1u << 6,
    // Points, directions and placements: what a placement of the assembly may share with
    // the geometry of a solid without using that geometry.
    kShareable = 1u << 7,
    kRepresentation = 1u << 8,  // simple, *REPRESENTATION, not a presentation one
    kGeometryRepType = 1u << 9, // simple *_REPRESENTATION that may hold solids
    kPresentation = 1u << 10,   // MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION, ...
    kStyled = 1u << 11,         // STYLED_ITEM, OVER_RIDING_STYLED_ITEM
    kContextStyled = 1u << 12,  // CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM
    kLayer = 1u << 13,          // PRESENTATION_LAYER_ASSIGNMENT
    kMappedItem = 1u << 14,
    kStyleByContext = 1u << 15, // PRESENTATION_STYLE_BY_CONTEXT: a style for one instance
    kConic = 1u << 16,          // CIRCLE, ELLIPSE
    kEdgeCurve = 1u << 17,      // EDGE_CURVE
};
// What bounds a piece's geometry in its box (step_pieces.h, VertexBox).
constexpr uint32_t kBounding = kVertexPoint | kEdgeCurve;
constexpr uint32_t kSolidLike = kSolid | kSurfaceModel;

// One entry per type of `types`. A complex type takes the geometric flags (solid, shell,
// face, ...) of its partial types; the role flags (representations, styles) are for simple
// records only.
std::vector<uint32_t> typeFlags(const TypeTable& types);

} // namespace scene::step
