// cad_reader_losses.h - what a STEP or IGES reader left behind without saying so: the file's
// entities that failed to read, and its faces. Open CASCADE skips a damaged entity and the
// shapes built on it, and still reports success: a damaged IGES file loaded 7 of its 45 faces
// in silence. Kept out of cad_loader.h, which stays free of Open CASCADE types.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <XSControl_WorkSession.hxx>

namespace scene {

struct ReaderLosses {
    uint32_t entities = 0;       // in the file
    uint32_t failedEntities = 0; // that the reader could not read
    uint32_t faceEntities = 0;   // faces the file holds (IGES 143, 144, 510; STEP faces)
};

// Counted over the model a reader's session read.
ReaderLosses readerLosses(const Handle(XSControl_WorkSession) & session);

// One warning for what was dropped, given the faces the loaded shapes hold; nothing where
// nothing was.
std::optional<std::string> lossWarning(const ReaderLosses& losses, uint32_t facesLoaded,
                                       const std::string& format);

} // namespace scene
