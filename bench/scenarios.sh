# The requests the HTTP benchmarks time (sourced by bench/http_bench.sh, bench/engine_compare.sh
# and bench/http_stages.sh), stated once: a name, its path and its body.
# shellcheck shell=bash disable=SC2034
SCENARIOS=(groove-wall entry-length)
declare -A SCENARIO_PATH=(
  [groove-wall]=/v1/roughness/groove-wall
  [entry-length]=/v1/entry-length
)
declare -A SCENARIO_BODY=(
  [groove-wall]='{"feed_mm": 0.2, "nose_radius_mm": 0.8, "minor_edge_angle_deg": 10}'
  [entry-length]='{"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}}'
)
