#pragma once
// Reading machine programs as text, independently of domain/program: the translation of a fanuc
// or sinumerik program to LinuxCNC (spec programs.md section 3, "Check by translation"), and the
// G0/G1 moves with their printed X Y Z F words, for the checks of section 1.3 on the text.

#include <string>
#include <string_view>
#include <vector>

namespace cutcalc::test::gcode {

// fanuc -> linuxcnc: the O line dropped, two-digit G and M words shortened (G01 -> G1, M03 -> M3);
// sinumerik -> linuxcnc: `;` comments -> `( )`, G710/G700 -> G21/G20, D1/D0 dropped.
// The lathe forms (grooving-cycle.md section 5.4): fanuc G99 -> G7 G95, `G50 S{m}` dropped and
// D{m} written into the next G96 block, G4 X -> G4 P, T{tt}{oo} -> T{tt} M6 G43; sinumerik
// DIAMON -> G7, LIMS= -> D, G4 F -> G4 P, `T{t} D1` -> T{t} M6 G43.
// `dialect` is "linuxcnc" (returned as it is), "fanuc" or "sinumerik".
std::string translate_to_linuxcnc(std::string_view program, std::string_view dialect);

struct TextMove {
  bool feed = false;           // G1 (else G0)
  double x = 0, y = 0, z = 0;  // after the move, program units
  double from_x = 0, from_y = 0, from_z = 0;
  double f = 0;  // the modal F in force (printed)
};

// The G0/G1 moves of a program in the LinuxCNC or translated form, from its printed words
// (absolute, G90; the position starts at 0 0 0). Comments are skipped.
std::vector<TextMove> moves_of(std::string_view program);

// The words of every block outside comments, upper case, one vector per line.
std::vector<std::vector<std::string>> words_of(std::string_view program, std::string_view dialect);

}  // namespace cutcalc::test::gcode
