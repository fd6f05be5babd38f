// procedural_parts.h - the parts catalogue of the procedural scenes (procedural.cpp): each
// geometry built once, to be placed many times, with the random numbers the scenes draw.
// Internal to src/scene.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace scene::procedural {

constexpr float kPi = 3.14159265358979323846f;

// splitmix64: tiny, fast and the same everywhere, unlike std:: distributions.
class Rng {
  public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // 24 random bits make an exactly representable float in [0, 1).
    float unit() { return float(next() >> 40) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
    int range(int lo, int hi) { return lo + int(next() % uint64_t(hi - lo + 1)); }

  private:
    uint64_t state_;
};

uint32_t makeBolt(Scene& s, float d, float length);
uint32_t makeNut(Scene& s, float d);
uint32_t makeWasher(Scene& s, float d);
// Three gears and their shaft in one geometry: a lay-shaft cluster of many tiny flank parts.
uint32_t makeGearCluster(Scene& s, int teeth);
uint32_t makeHose(Scene& s, Rng& rng, float length, int rings);
uint32_t makeRail(Scene& s, float length, float height);
uint32_t makeFloorPan(Scene& s, glm::vec2 size);
uint32_t makeTubeBar(Scene& s, float length, std::string name);
uint32_t makeBracket(Scene& s);
uint32_t makeTyre(Scene& s);
uint32_t makeRim(Scene& s);
uint32_t makeDisc(Scene& s);
uint32_t makeCasting(Scene& s, float length, float radius, int segments);
uint32_t makeEngineBlock(Scene& s, glm::vec3 size);
uint32_t makeFinPack(Scene& s, int fins, glm::vec2 size);
uint32_t makePulley(Scene& s, float r);

} // namespace scene::procedural
