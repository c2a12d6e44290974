#pragma once

namespace cutcalc::domain {

// Up-milling ("встречное") and down-milling ("попутное"); each paper defines which is which.
enum class MillingSense { up, down };

}  // namespace cutcalc::domain
