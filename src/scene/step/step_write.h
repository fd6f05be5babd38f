// step_write.h - the texts the splitter hands out (step_write.cpp): the skeleton, with each
// geometry representation's solids replaced by a set of two points, and a piece's records
// with a product of its own. Records are copied byte for byte; new ones are numbered above
// the file's largest entity number.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/step/step_index.h"
#include "scene/step/step_pieces.h"
#include "scene/step/step_plan.h"

namespace scene::step {

// The entity number of the skeleton's GEOMETRIC_SET for geometry representation `rep`.
uint64_t dummySetId(const StepIndex& index, uint32_t rep);

std::string skeletonText(const StepIndex& index, const Plan& plan,
                         const std::vector<PieceFacts>& pieces);

// The records a piece adds to its representation's closure: a product that uses the
// representation and a presentation of its styled items.
std::string pieceChain(const StepIndex& index, const Plan& plan, uint32_t rep,
                       const std::vector<uint32_t>& styled);

// The bytes of a piece's text around its records and chain (header, DATA;, ENDSEC; ...).
uint64_t pieceFrameBytes(const StepIndex& index);

std::string pieceText(const StepIndex& index, const std::vector<uint32_t>& records,
                      const std::string& chain);

} // namespace scene::step
