// Welds the surface cache's stored vertices (render/cache/stored_vertex_weld.h): each vertex looks itself
// up in an open-addressing hash table by its position, normal · 2^kind and the patch and (u, v) it
// was evaluated at (the canonical patch on a patch edge, a corner's owner: one surface point,
// evaluated once), and takes as its index the vertex that is there first with the same words, else
// inserts itself. Copies on the patches around a point so weld, across blocks too (on an infinitely
// sharp crease only those of one patch: there each side keeps its own normal and edge point); their
// tessellation grids differ, and a frame that draws the grid draws the vertices as captured. The
// draw then fetches and shades each such vertex once, as a welded static buffer's are. Each vertex
// also writes whether it is its own index, for the prefix sum that numbers the distinct vertices
// (shaders/compact_comp.glsl).
#include "shaders/compute_pass.glsl"
layout(std430, binding = kBindingStoredVertices) readonly buffer StoredVertices { uint stored[]; };  // 12 words a vertex, 9 drawn
const int kKeyWords = 9;  // of a stored vertex's 12: position and normal (0–5), patch and (u, v) evaluated (9–11)
uint key_word(uint v, int k) { return stored[12u * v + uint(k < 6 ? k : k + 3)]; }
layout(std430, binding = kBindingWeldTable) buffer WeldTable { uint slots[]; };                    // 0 or vertex + 1
layout(std430, binding = kBindingStoredIndices) writeonly buffer StoredIndices { uint indices[]; };
layout(std430, binding = kBindingScanValues) writeonly buffer Distinct { uint distinct[]; };  // per vertex: 1 if its own index
uniform int u_slots;  // table size, at least twice the vertices: a free slot is always found

void keep(uint v, uint index) {
  indices[v] = index;
  distinct[v] = index == v ? 1u : 0u;
}

void main() {
  int i = compute_invocation();
  if (i < 0) return;
  uint v = uint(i), slots_in_table = uint(u_slots);
  uint word[kKeyWords];
  uint hash = 2166136261u;  // FNV-1a over the key's words
  for (int k = 0; k < kKeyWords; ++k) {
    word[k] = key_word(v, k);
    hash = (hash ^ word[k]) * 16777619u;
  }
  // At most one probe per slot: the table has twice the range's slots, so a free one comes long before;
  // the bound keeps a driver from spinning should it not.
  uint slot = (hash ^ (hash >> 16)) % slots_in_table;
  for (uint probe = 0u; probe < slots_in_table; ++probe, slot = slot + 1u == slots_in_table ? 0u : slot + 1u) {
    uint held = atomicCompSwap(slots[slot], 0u, v + 1u);
    if (held == 0u) {
      keep(v, v);
      return;
    }
    uint w = held - 1u;
    bool same = true;
    for (int k = 0; k < kKeyWords; ++k) same = same && key_word(w, k) == word[k];
    if (same) {
      keep(v, w);
      return;
    }
  }
  keep(v, v);  // not welded: drawn as captured
}
