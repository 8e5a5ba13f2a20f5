// An axis-aligned box [m]: fluid blocks, rectangles, clamp regions and the divergence domain.
#pragma once
#include "core/vec.h"

namespace slamsph {

struct Box {
  Vec2 min, max;
};

inline bool inside(const Box& b, Vec2 p) {
  return p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y;
}

}  // namespace slamsph
