// part_vertices.cpp - choosing, for every triangle, the corner that leads it.
//
// A vertex that one part alone uses can lead any triangle of that part. A vertex that several
// parts share can lead the triangles of one of them only, its owner; another part needs a
// copy. A triangle with a corner of its own part alone keeps its first such corner first (no
// rotation at all where parts share no vertex, as in CAD tessellations). The others are
// settled most constrained first (fewest corners still unowned): one takes the unowned corner
// that settles the most triangles of its part, and one left with none gets a copy of a corner
// for its part, which the part's other triangles at that corner then share.
#include "scene/part_vertices.h"

#include <queue>

#include "scene/part_data.h"

namespace scene {
namespace {

constexpr uint32_t none = UINT32_MAX;

class LeadChooser {
  public:
    LeadChooser(const uint32_t* indices, std::vector<uint32_t> parts, uint32_t vertexCount)
        : in_(indices), parts_(std::move(parts)), vertexCount_(vertexCount),
          triangleCount_(uint32_t(parts_.size())), start_(vertexCount + 1, 0),
          owner_(vertexCount, none), lead_(triangleCount_, none), corner_(triangleCount_, 0),
          free_(triangleCount_, 0) {
        indexTrianglesByVertex();
        settleExclusive();
        settleShared();
    }

    // Writes the rotated triangles (lead first, winding kept) and the copies made.
    void write(uint32_t* out, std::vector<std::pair<uint32_t, uint32_t>>& copies) const {
        for (uint32_t t = 0; t < triangleCount_; ++t) {
            const uint32_t* tri = in_ + 3 * t;
            const uint32_t c = corner_[t];
            out[3 * t] = lead_[t];
            out[3 * t + 1] = tri[(c + 1) % 3];
            out[3 * t + 2] = tri[(c + 2) % 3];
        }
        copies = copies_;
    }

  private:
    void indexTrianglesByVertex() {
        for (uint32_t i = 0; i < 3 * triangleCount_; ++i) ++start_[in_[i] + 1];
        for (uint32_t v = 0; v < vertexCount_; ++v) start_[v + 1] += start_[v];
        rows_.resize(3 * triangleCount_);
        std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
        for (uint32_t i = 0; i < 3 * triangleCount_; ++i) rows_[fill[in_[i]]++] = i / 3;
        exclusive_.assign(vertexCount_, true);
        for (uint32_t v = 0; v < vertexCount_; ++v)
            for (uint32_t k = start_[v]; k < start_[v + 1]; ++k)
                if (parts_[rows_[k]] != parts_[rows_[start_[v]]]) exclusive_[v] = false;
    }

    void settle(uint32_t t, uint32_t corner, uint32_t lead) {
        corner_[t] = corner;
        lead_[t] = lead;
    }
    bool settled(uint32_t t) const { return lead_[t] != none; }

    void settleExclusive() {
        for (uint32_t t = 0; t < triangleCount_; ++t)
            for (uint32_t c = 0; c < 3 && !settled(t); ++c)
                if (exclusive_[in_[3 * t + c]]) settle(t, c, in_[3 * t + c]);
    }

    // Unsettled triangles of `part` at vertex v.
    uint32_t waiting(uint32_t v, uint32_t part) const {
        uint32_t n = 0;
        for (uint32_t k = start_[v]; k < start_[v + 1]; ++k)
            n += !settled(rows_[k]) && parts_[rows_[k]] == part;
        return n;
    }

    // Settles every waiting triangle of `part` at v with `lead` (v itself or its copy).
    void settleAt(uint32_t v, uint32_t part, uint32_t lead) {
        for (uint32_t k = start_[v]; k < start_[v + 1]; ++k) {
            const uint32_t t = rows_[k];
            if (settled(t) || parts_[t] != part) continue;
            for (uint32_t c = 0; c < 3; ++c)
                if (in_[3 * t + c] == v) {
                    settle(t, c, lead);
                    break;
                }
        }
    }

    void settleShared() {
        using Entry = std::pair<uint32_t, uint32_t>; // (corners still unowned, triangle)
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
        for (uint32_t t = 0; t < triangleCount_; ++t) {
            if (settled(t)) continue;
            for (uint32_t c = 0; c < 3; ++c) free_[t] += owner_[in_[3 * t + c]] == none;
            queue.push({free_[t], t});
        }
        while (!queue.empty()) {
            const auto [count, t] = queue.top();
            queue.pop();
            if (settled(t) || count != free_[t]) continue; // settled since, or stale
            const uint32_t part = parts_[t];
            const uint32_t* tri = in_ + 3 * t;
            // The corner that settles the most triangles of this part: unowned, or, with
            // none left, one to copy (a copy made earlier for this part would have settled
            // this triangle already).
            uint32_t best = 0, bestGain = 0;
            for (uint32_t c = 0; c < 3; ++c) {
                if (count > 0 && owner_[tri[c]] != none) continue;
                const uint32_t gain = waiting(tri[c], part);
                if (gain > bestGain) best = c, bestGain = gain;
            }
            const uint32_t v = tri[best];
            if (count == 0) {
                copies_.push_back({v, part});
                settleAt(v, part, vertexCount_ + uint32_t(copies_.size()) - 1);
                continue;
            }
            owner_[v] = part;
            settleAt(v, part, v);
            for (uint32_t k = start_[v]; k < start_[v + 1]; ++k) {
                const uint32_t u = rows_[k];
                if (settled(u)) continue;
                --free_[u];
                queue.push({free_[u], u});
            }
        }
    }

    const uint32_t* in_;
    std::vector<uint32_t> parts_;
    uint32_t vertexCount_, triangleCount_;
    std::vector<uint32_t> start_, rows_; // triangles by vertex (compressed rows)
    std::vector<bool> exclusive_;        // one part alone uses the vertex
    std::vector<uint32_t> owner_;        // shared vertices: the part it leads for, or none
    std::vector<uint32_t> lead_;         // per triangle: its first vertex (maybe a copy)
    std::vector<uint32_t> corner_;       // per triangle: the corner that leads
    std::vector<uint32_t> free_;         // per triangle: shared corners still unowned
    std::vector<std::pair<uint32_t, uint32_t>> copies_; // (vertex copied, part)
};

} // namespace

PartVertices buildPartVertices(const Scene& scene) {
    PartVertices out;
    out.vertices.reserve(scene.vertices.size());
    out.localPart.reserve(scene.vertices.size());
    out.indices = scene.indices; // each geometry's range is rewritten in place
    for (uint32_t g = 0; g < scene.geometries.size(); ++g) {
        const Geometry& geometry = scene.geometries[g];
        std::vector<uint32_t> parts = trianglePartsOf(scene, g);
        const LeadChooser chooser(scene.indices.data() + geometry.firstIndex, parts,
                                  geometry.vertexCount);
        std::vector<std::pair<uint32_t, uint32_t>> copies;
        chooser.write(out.indices.data() + geometry.firstIndex, copies);

        // The geometry's own vertices, then its copies; each with the part it leads for.
        out.firstVertex.push_back(static_cast<uint32_t>(out.vertices.size()));
        out.vertexCount.push_back(geometry.vertexCount + uint32_t(copies.size()));
        const Vertex* own = scene.vertices.data() + geometry.firstVertex;
        out.vertices.insert(out.vertices.end(), own, own + geometry.vertexCount);
        std::vector<uint32_t> leads(geometry.vertexCount, 0);
        for (uint32_t t = 0; t < geometry.triangleCount; ++t) {
            const uint32_t lead = out.indices[geometry.firstIndex + 3 * t];
            if (lead < geometry.vertexCount) leads[lead] = parts[t];
        }
        out.localPart.insert(out.localPart.end(), leads.begin(), leads.end());
        for (const auto& [source, part] : copies) {
            out.vertices.push_back(own[source]);
            out.localPart.push_back(part);
        }
        out.addedVertices += copies.size();
    }
    return out;
}

} // namespace scene
