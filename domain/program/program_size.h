#pragma once
// The size cap every program writer shares (programs.md section 1.2 "as the polygon's",
// polygon-holes.md section 10, lathe-flat.md section 6.3): one fact, the largest program a writer
// may emit. Each family counts the blocks that make its program long (the polygon its arc blocks,
// the lathe flat its cutting blocks, the pass program every block) and refuses a larger program
// with this limit before any text is written.

namespace cutcalc::domain::program {

inline constexpr double kMaxProgramBlocks = 200000;

}  // namespace cutcalc::domain::program
