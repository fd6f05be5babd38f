// cad_reader_losses.cpp - the entities and faces a reader dropped (cad_reader_losses.h).
#include "scene/cad/cad_reader_losses.h"

#include <IGESData_IGESEntity.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_InterfaceModel.hxx>
#include <StepShape_Face.hxx>

namespace scene {

ReaderLosses readerLosses(const Handle(XSControl_WorkSession) & session) {
    ReaderLosses out;
    if (session.IsNull() || session->Model().IsNull()) return out;
    const Handle(Interface_InterfaceModel) model = session->Model();
    out.entities = uint32_t(model->NbEntities());
    for (int i = 1; i <= model->NbEntities(); ++i) {
        const Handle(Standard_Transient) entity = model->Value(i);
        if (const auto iges = Handle(IGESData_IGESEntity)::DownCast(entity); !iges.IsNull()) {
            const int type = iges->TypeNumber();
            out.faceEntities += type == 143 || type == 144 || type == 510;
        } else if (!Handle(StepShape_Face)::DownCast(entity).IsNull()) {
            ++out.faceEntities;
        }
    }
    // The checks the reading itself recorded (not a full semantic check, which takes long).
    Interface_CheckIterator checks = session->ModelCheckList(false);
    for (checks.Start(); checks.More(); checks.Next())
        out.failedEntities += checks.Number() > 0 && checks.Value()->HasFailed();
    return out;
}

std::optional<std::string> lossWarning(const ReaderLosses& losses, uint32_t facesLoaded,
                                       const std::string& format) {
    const uint32_t missing =
        losses.faceEntities > facesLoaded ? losses.faceEntities - facesLoaded : 0;
    if (losses.failedEntities == 0 && missing == 0) return std::nullopt;
    std::string text = "the " + format + " reader dropped ";
    if (losses.failedEntities)
        text += std::to_string(losses.failedEntities) + " of the file's " +
                std::to_string(losses.entities) + " entities (they failed to read)";
    if (losses.failedEntities && missing) text += " and ";
    if (missing)
        text +=
            std::to_string(missing) + " of its " + std::to_string(losses.faceEntities) + " faces";
    return text + ": the model shown is incomplete";
}

} // namespace scene
