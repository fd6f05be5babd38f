// cad_jobs.cpp - jobs and answers of a CAD load's workers as bytes (cad_jobs.h).
#include "scene/cad/cad_jobs.h"

#include <stdexcept>

#include "scene/cad/scene_codec.h"

namespace scene::cad {
namespace {

template <typename IO, typename M>
void meshFields(IO& io, M& m) {
    fields(io, m.deflection, m.angularDeflection, m.levels, m.healing, m.maxTriangles);
}

template <typename IO, typename F>
void figureFields(IO& io, F& f) {
    fields(io, f.parseMs, f.transferMs, f.healingMs, f.meshMs, f.buildMs, f.levelsMs, f.encodeMs,
           f.peakBytes, f.healed, f.entities, f.failedEntities, f.faceEntities);
}

template <typename IO, typename L>
void leafFields(IO& io, L& leaf) {
    fields(io, leaf.piece, leaf.faces, leaf.world, leaf.name, leaf.product, leaf.group);
    bool hasColor = leaf.color.has_value();
    io(hasColor);
    glm::dvec4 color = leaf.color.value_or(glm::dvec4(0.0));
    io(color);
    if constexpr (std::is_same_v<IO, ByteReader>)
        leaf.color = hasColor ? std::optional<glm::dvec4>(color) : std::nullopt;
    fields(io, leaf.boxMin, leaf.boxMax);
}

template <typename IO, typename C>
void candidateFields(IO& io, C& c) {
    io(c.geometry);
    io.records(c.chains, [](auto& io, auto& chain) {
        io.records(chain, [](auto& io, auto& level) {
            io(level.vertices);
            io.records(level.parts, [](auto& io, auto& part) { io(part); });
            fields(io, level.triangles, level.bytes, level.error);
        });
    });
}

template <typename IO, typename R>
void loadFigureFields(IO& io, R& r) {
    fields(io, r.readMs, r.tessellationMs, r.levelsMs, r.deflection, r.faces, r.facesFailed);
    io.records(r.warnings, [](auto& io, auto& w) { io(w); });
}

template <typename Answer, typename Fields>
Answer decodeWith(std::string_view bytes, Fields fieldsOf) {
    ByteReader in(bytes);
    Answer answer;
    fieldsOf(in, answer);
    if (!in.done()) throw std::runtime_error("bytes after a worker's message");
    return answer;
}

template <typename Value, typename Fields>
std::string encodeWith(const Value& value, Fields fieldsOf) {
    ByteWriter out;
    fieldsOf(out, const_cast<Value&>(value)); // the writer only reads
    return std::move(out.bytes());
}

constexpr auto skeletonJobFields = [](auto& io, auto& j) { fields(io, j.text, j.dummySets); };
constexpr auto skeletonAnswerFields = [](auto& io, auto& a) {
    io.records(a.leaves, [](auto& io, auto& leaf) { leafFields(io, leaf); });
    fields(io, a.entities, a.failedEntities, a.ms);
};
constexpr auto pieceJobFields = [](auto& io, auto& j) {
    fields(io, j.piece, j.text, j.objectFaces);
    meshFields(io, j.mesh);
};
constexpr auto wholeJobFields = [](auto& io, auto& j) {
    fields(io, j.path, j.options.deflection, j.options.angularDeflection, j.options.maxTriangles,
           j.options.healing, j.levels);
};
constexpr auto stepExportJobFields = [](auto& io, auto& j) {
    fields(io, j.source, j.out, j.healing, j.keep);
    io.records(j.paths, [](auto& io, auto& p) { io(p); });
};

// The scenes go before these, through the cache's codec, which checks what it reads
// (scene::validate).
constexpr auto pieceAnswerFields = [](auto& io, auto& a) {
    io(a.piece);
    io.records(a.brep, [](auto& io, auto& b) { io(b); });
    io.records(a.candidates, [](auto& io, auto& c) { candidateFields(io, c); });
    io.records(a.warnings, [](auto& io, auto& w) { io(w); });
    fields(io, a.faces, a.facesFailed);
    figureFields(io, a.figures);
};
constexpr auto wholeAnswerFields = [](auto& io, auto& a) {
    loadFigureFields(io, a.result);
    io.records(a.brep, [](auto& io, auto& b) { io(b); });
    figureFields(io, a.figures);
};

template <typename Answer, typename Fields>
std::string encodeAfterScene(const Scene& scene, const Answer& answer, Fields fieldsOf) {
    ByteWriter out;
    encodeScene(scene, out);
    fieldsOf(out, const_cast<Answer&>(answer));
    return std::move(out.bytes());
}

template <typename Answer, typename Fields>
Answer decodeAfterScene(std::string_view bytes, Scene Answer::*scene, Fields fieldsOf) {
    ByteReader in(bytes);
    Answer answer;
    answer.*scene = decodeScene(in);
    fieldsOf(in, answer);
    if (!in.done()) throw std::runtime_error("bytes after a worker's message");
    return answer;
}

} // namespace

std::string encodeProgress(const char* stage, double fraction) {
    ByteWriter out;
    out.putString(stage);
    out.put(fraction);
    return std::move(out.bytes());
}

std::pair<std::string, double> decodeProgress(std::string_view bytes) {
    ByteReader in(bytes);
    std::string stage = in.getString();
    const double fraction = in.get<double>();
    return {stage, fraction};
}

std::string encode(const SkeletonJob& job) {
    return encodeWith(job, skeletonJobFields);
}
std::string encode(const SkeletonAnswer& answer) {
    return encodeWith(answer, skeletonAnswerFields);
}
std::string encode(const PieceJob& job) {
    return encodeWith(job, pieceJobFields);
}
std::string encode(const PieceAnswer& answer) {
    return encodeAfterScene(answer.mesh, answer, pieceAnswerFields);
}
std::string encode(const WholeFileJob& job) {
    return encodeWith(job, wholeJobFields);
}
std::string encode(const WholeFileAnswer& answer) {
    return encodeAfterScene(answer.result.scene, answer, wholeAnswerFields);
}
std::string encode(const StepExportJob& job) {
    return encodeWith(job, stepExportJobFields);
}

SkeletonJob decodeSkeletonJob(std::string_view bytes) {
    return decodeWith<SkeletonJob>(bytes, skeletonJobFields);
}
SkeletonAnswer decodeSkeletonAnswer(std::string_view bytes) {
    return decodeWith<SkeletonAnswer>(bytes, skeletonAnswerFields);
}
PieceJob decodePieceJob(std::string_view bytes) {
    return decodeWith<PieceJob>(bytes, pieceJobFields);
}
PieceAnswer decodePieceAnswer(std::string_view bytes) {
    return decodeAfterScene(bytes, &PieceAnswer::mesh, pieceAnswerFields);
}
WholeFileJob decodeWholeFileJob(std::string_view bytes) {
    return decodeWith<WholeFileJob>(bytes, wholeJobFields);
}
WholeFileAnswer decodeWholeFileAnswer(std::string_view bytes) {
    ByteReader in(bytes);
    WholeFileAnswer answer;
    answer.result.scene = decodeScene(in);
    wholeAnswerFields(in, answer);
    if (!in.done()) throw std::runtime_error("bytes after a worker's message");
    return answer;
}
StepExportJob decodeStepExportJob(std::string_view bytes) {
    return decodeWith<StepExportJob>(bytes, stepExportJobFields);
}

} // namespace scene::cad
