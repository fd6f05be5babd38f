// step_split.h - a STEP file's text cut apart before Open CASCADE parses it, so that worker
// processes can each parse, transfer and mesh a share of it (scene/cad/cad_workers.h).
//
// Open CASCADE 7.6 reads a STEP file on one thread, and its readers are not safe to run in
// threads, so idview splits the text itself, with a lexer of its own, into:
// - the skeleton: every entity of the assembly structure (products, their instances and
//   placements, units, names, the styles that are not on geometry), with each geometry
//   representation's solid items replaced by one small GEOMETRIC_SET of two points (the corners
//   of the box of its vertices, in the representation's own units). Read by Open CASCADE like
//   any STEP file, it gives the very assembly tree, placements and names the whole file would,
//   in a fraction of the time, and each leaf's shape is the set of one representation, which
//   names the piece that holds its geometry. A style that holds for one instance (Open
//   CASCADE writes an instance's colour as a style by context on the solid) is moved from the
//   solid onto the set, so that the reader gives it to that instance again; the pieces carry
//   the products' and the faces' colours.
// - one piece per geometry representation: the representation with everything it references
//   (its solids, their faces down to the points, its units), the styled items on those and a
//   presentation representation listing them, and a product of its own that uses the
//   representation, so that Open CASCADE's XDE reader gives it one shape with the colours of
//   its faces and solids.
// Plain C++, no Open CASCADE: the text is only lexed and copied.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace scene::step {

// The objects idview makes of one geometry representation's shape, as the CAD loader splits a
// shape (scene/cad/cad_read.h, splitSolids): one object per solid when it holds two or more
// solids, or a solid beside faces of no solid, plus one object for the faces of no solid; else
// one object with every face. Face counts are of distinct face entities, in the order Open
// CASCADE's TopExp::MapShapes visits them (items in order, shells in order, faces in order, a
// face met again not counted twice). The counts are of the text's face entities: where Open
// CASCADE's reader splits a face as it fixes the shape (ShapeFix's FixSplitFaceMode, on by
// default), its shape has more faces than counted here (KiCad's SSO-4 model: 96 face
// entities, 104 faces read), so a loader takes them as a forecast, not as a promise.
struct RepLayout {
    std::vector<uint32_t> objectFaces; // per object, its faces
    bool split = false;                // one object per solid (named "solid N"), ...
    bool freeFaces = false;            // ... and the last one the faces of no solid
    uint32_t solids = 0;
    uint64_t faces() const;
};

// One geometry representation and what the loader needs of it.
struct Piece {
    uint64_t rep = 0;      // the representation's entity number (#rep)
    uint64_t dummySet = 0; // the skeleton's GEOMETRIC_SET that stands for its solid items
    uint64_t bytes = 0;    // the size of the piece's text, to schedule the largest first
    RepLayout layout;
    bool hasBox = false; // false: no vertex, the two points are both at the origin
    // The box's corners, the dummy set's two points, in the file's numbers (the
    // representation's own units; Open CASCADE converts them when it reads the skeleton).
    std::array<double, 3> boxMin{}, boxMax{};
};

// Why a file cannot be split (then it is read whole, as before): a syntax the lexer does not
// take, or a construct the skeleton could not stand for (a solid used elsewhere than by one
// representation, styles that depend on an assembly context, ...).
struct NotSplit {
    std::string reason; // one line, for --stats and a warning
};

class StepSplit {
  public:
    // Lexes `path` (memory-mapped, never copied whole) and works out the skeleton and pieces.
    // Throws std::runtime_error only where the file cannot be opened or mapped; a file whose
    // text cannot be split gives notSplit() instead.
    explicit StepSplit(const std::string& path);
    ~StepSplit();
    StepSplit(const StepSplit&) = delete;
    StepSplit& operator=(const StepSplit&) = delete;

    const std::optional<NotSplit>& notSplit() const;
    // The pieces in the order of their representations in the file.
    const std::vector<Piece>& pieces() const;
    // A complete STEP file (the original header, a DATA section, ENDSEC, END-ISO-10303-21).
    // Both throw std::logic_error where notSplit() is set.
    std::string skeleton() const;
    // A complete STEP file holding piece `index` (see the top of this file). Made on demand, so
    // that no more than the pieces in flight are held as text at once. Calls from several
    // threads are safe (they share one set of visit marks, taken in turn).
    std::string pieceText(size_t index) const;

    // What the lexer saw, for --stats: entities, bytes, and milliseconds spent.
    uint64_t entities() const;
    uint64_t bytes() const;
    uint64_t indexBytes() const; // what the index and the plan hold in memory
    double lexMs() const;        // indexing the entities and their references
    double splitMs() const;      // working out the skeleton and the pieces

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace scene::step
