// prelude.glsl - what every shader of the scene pipelines starts with: the shared structs and
// buffer references (buffers.glsl), the push constant block and the loads every stage makes.
#include "buffers.glsl"

layout(push_constant, std430) uniform PushBlock {
    DrawPush push;
};

// Whether unique part `id` is in the bitset at `address` (see shared.h).
bool partInSet(uint64_t address, uint id) {
    return (UintsRef(address).values[id >> 5] & (1u << (id & 31u))) != 0u;
}

FrameData loadFrame() {
    return FrameRef(push.frameAddress).frame;
}

ObjectData loadObject(uint64_t objectsAddress, uint objectIndex) {
    return ObjectsRef(objectsAddress).objects[objectIndex];
}

// The current draw's parameters, however the per-draw mode delivers them (IDV_MODE_*).
DrawData loadDraw(FrameData frame, uint drawIndex) {
#if IDV_MODE_PUSH
    return push.draw;
#else
    return DrawsRef(frame.drawsAddress).draws[drawIndex];
#endif
}
