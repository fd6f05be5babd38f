// step_types.cpp - the type flags of step_types.h, from the keywords.
#include "scene/step/step_types.h"

#include <string_view>

namespace scene::step {
namespace {

bool endsWith(std::string_view text, std::string_view end) {
    return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

uint32_t geometricFlags(std::string_view name) {
    if (name == "MANIFOLD_SOLID_BREP" || name == "BREP_WITH_VOIDS" || name == "FACETED_BREP")
        return kSolid;
    if (name == "SHELL_BASED_SURFACE_MODEL" || name == "FACE_BASED_SURFACE_MODEL")
        return kSurfaceModel;
    if (name == "CLOSED_SHELL" || name == "OPEN_SHELL" || name == "ORIENTED_CLOSED_SHELL" ||
        name == "ORIENTED_OPEN_SHELL" || name == "CONNECTED_FACE_SET")
        return kShell;
    if (name == "ADVANCED_FACE" || name == "FACE_SURFACE") return kFace;
    if (name == "ORIENTED_FACE") return kOrientedFace;
    if (name == "VERTEX_POINT") return kVertexPoint;
    if (name == "CIRCLE" || name == "ELLIPSE") return kConic;
    if (name == "EDGE_CURVE") return kEdgeCurve;
    if (name == "CARTESIAN_POINT") return kCartesianPoint | kShareable;
    if (name == "DIRECTION" || name == "AXIS2_PLACEMENT_3D") return kShareable;
    return 0;
}

bool isPresentation(std::string_view name) {
    return name.find("PRESENTATION_REPRESENTATION") != std::string_view::npos ||
           name == "DRAUGHTING_MODEL" || name == "PRESENTATION_AREA" || name == "PRESENTATION_VIEW";
}

uint32_t roleFlags(std::string_view name) {
    if (isPresentation(name)) return kPresentation;
    if (name == "STYLED_ITEM" || name == "OVER_RIDING_STYLED_ITEM") return kStyled;
    if (name == "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM") return kContextStyled;
    if (name == "PRESENTATION_LAYER_ASSIGNMENT") return kLayer;
    if (name == "MAPPED_ITEM") return kMappedItem;
    if (name == "PRESENTATION_STYLE_BY_CONTEXT") return kStyleByContext;
    if (!endsWith(name, "REPRESENTATION")) return 0;
    if (endsWith(name, "_REPRESENTATION") && name != "DEFINITIONAL_REPRESENTATION")
        return kRepresentation | kGeometryRepType;
    return kRepresentation;
}

} // namespace

std::vector<uint32_t> typeFlags(const TypeTable& types) {
    std::vector<uint32_t> flags(types.size(), 0);
    for (uint32_t t = 0; t < types.size(); ++t) {
        for (std::string_view part : types.parts(t)) flags[t] |= geometricFlags(part);
        if (!types.isComplex(t)) flags[t] |= roleFlags(types.parts(t)[0]);
    }
    return flags;
}

} // namespace scene::step
