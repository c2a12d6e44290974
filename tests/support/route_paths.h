#pragma once
// The calculation routes the api tests post to (the route table: api/routes.cpp), named once for
// every test file of a route.

namespace cutcalc::testing {

inline constexpr const char* kEntryLengthPath = "/v1/entry-length";
inline constexpr const char* kMainTimePath = "/v1/main-time";
inline constexpr const char* kMainTimeProgramPath = "/v1/main-time/program";
inline constexpr const char* kResultantSpeedsPath = "/v1/resultant-speeds";
inline constexpr const char* kPolygonGcodePath = "/v1/polygon-hole/gcode";
inline constexpr const char* kGrooveWallPath = "/v1/roughness/groove-wall";
inline constexpr const char* kBoreMillingPath = "/v1/roughness/bore-milling";
inline constexpr const char* kLatheFlatPath = "/v1/lathe-flat";
inline constexpr const char* kGroovingCyclePath = "/v1/grooving/cycle";

}  // namespace cutcalc::testing
