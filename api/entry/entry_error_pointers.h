#pragma once
// The members the entry-length, main-time and pass-program requests hold for each domain error of
// the entry model (their field names are the same). The other codes (no_contact, and the pass
// program's word_prints_as_zero and pass_program_too_large) are about the combination of inputs.

#include "api/domain_error_mapping.h"

namespace cutcalc::api::entry {

inline constexpr ErrorPointer kEntryErrorPointers[] = {
    {domain::ErrorCode::stroke_shorter_than_entry, "/length_mm"},
    {domain::ErrorCode::entry_arc_wider_than_diameter, "/entry/width_mm"},
    {domain::ErrorCode::exit_arc_wider_than_diameter, "/exit/width_mm"},
    // Also when a convex exit arc has no width_mm: its implied width 2 radius_mm is at fault.
    {domain::ErrorCode::exit_width_mismatch, "/exit/width_mm"},
    {domain::ErrorCode::offset_with_several_passes, "/offset_mm"},
    {domain::ErrorCode::allowance_wider_than_part, "/allowance/width_mm"},
    {domain::ErrorCode::allowance_not_full_width, "/allowance/width_mm"},
    {domain::ErrorCode::width_of_cut_exceeds_diameter, "/allowance/width_of_cut_mm"},
    {domain::ErrorCode::entry_feed_exceeds_feed, "/entry_feed_per_tooth_mm"},
    {domain::ErrorCode::too_many_lateral_passes, "/allowance/width_of_cut_mm"},
    {domain::ErrorCode::too_many_depth_passes, "/allowance/depth_of_cut_mm"},
    {domain::ErrorCode::finish_depth_not_below_depth, "/finish/depth_of_cut_mm"},
};

}  // namespace cutcalc::api::entry
