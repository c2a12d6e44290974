#!/usr/bin/python3
"""Writes the oracle's test programs: tests/oracle/programs/<id>.ngc and manifest.json.

    /usr/bin/python3 tools/oracle/make_programs.py [--cutcalc http://127.0.0.1:18099]

The hand-made programs are defined below. With --cutcalc, the programs cutcalc writes itself are
asked from a running cutcalc (Accept: text/plain, LinuxCNC dialect) with the requests in CUTCALC
below; without it, the cutcalc programs already in the manifest are kept as they are.
Every program is short (a few seconds at most) and ends with a move and M2: the oracle counts the
time from the first to the last move, nothing after it. Then tools/oracle/record.py times them.
"""
import argparse
import json
import math
import os
import sys
import urllib.request

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
OUT = os.path.join(ROOT, "tests", "oracle", "programs")

PROFILES = {
    "hobby_router": {
        "kind": "mill",
        "axes": {"x": {"max_velocity_mm_per_min": 3000, "max_acceleration_mm_per_s2": 200},
                 "y": {"max_velocity_mm_per_min": 3000, "max_acceleration_mm_per_s2": 200},
                 "z": {"max_velocity_mm_per_min": 1500, "max_acceleration_mm_per_s2": 100}},
        "max_feed_mm_per_min": 3000, "servo_period_ms": 1.0, "max_spindle_rpm": 24000,
    },
    # exactly the machine of shared/reference/next/program-time.json
    "router": {
        "kind": "mill",
        "axes": {"x": {"max_velocity_mm_per_min": 12000, "max_acceleration_mm_per_s2": 1000},
                 "y": {"max_velocity_mm_per_min": 12000, "max_acceleration_mm_per_s2": 1000},
                 "z": {"max_velocity_mm_per_min": 8000, "max_acceleration_mm_per_s2": 600}},
        "max_feed_mm_per_min": 12000, "servo_period_ms": 1.0,
    },
    "machining_centre": {
        "kind": "mill",
        "axes": {"x": {"max_velocity_mm_per_min": 36000, "max_acceleration_mm_per_s2": 4000},
                 "y": {"max_velocity_mm_per_min": 36000, "max_acceleration_mm_per_s2": 4000},
                 "z": {"max_velocity_mm_per_min": 36000, "max_acceleration_mm_per_s2": 4000},
                 "c": {"max_velocity_deg_per_min": 18000, "max_acceleration_deg_per_s2": 3600}},
        "max_feed_mm_per_min": 36000, "servo_period_ms": 1.0, "max_spindle_rpm": 12000,
    },
    "lathe": {
        "kind": "lathe",
        "axes": {"x": {"max_velocity_mm_per_min": 10000, "max_acceleration_mm_per_s2": 1500},
                 "z": {"max_velocity_mm_per_min": 12000, "max_acceleration_mm_per_s2": 1500},
                 "c": {"max_velocity_deg_per_min": 21600, "max_acceleration_deg_per_s2": 3600}},
        "max_feed_mm_per_min": 12000, "servo_period_ms": 1.0, "max_spindle_rpm": 4000,
    },
}


def num(v):
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def chords(cx, cy, r, n, start_deg=0.0, turn_deg=360.0):
    """G1 lines along n chords of a circle, counter-clockwise from start_deg."""
    lines = []
    for i in range(1, n + 1):
        a = math.radians(start_deg + turn_deg * i / n)
        lines.append(f"G1 X{num(cx + r * math.cos(a))} Y{num(cy + r * math.sin(a))}")
    return lines


def square(size, x0=0.0, y0=0.0):
    return [f"G1 X{num(x0 + size)}", f"G1 Y{num(y0 + size)}", f"G1 X{num(x0)}", f"G1 Y{num(y0)}"]


MILL = "G21 G90 G17 G94"

# (id, profile, category, about, body lines); the header "G21 G90 G17 G94 <mode>" and M2 are added.
CASES = []


def case(cid, profile, category, about, mode, body, header=MILL):
    head = f"{header} {mode}".strip()
    CASES.append({"id": cid, "profile": profile, "category": category, "about": about,
                  "text": "\n".join([head] + body + ["M2"]) + "\n"})


# --- single moves -------------------------------------------------------------------------------
case("single-rapid-x60-hobby", "hobby_router", "single", "one rapid along X, exact stop: a trapezoid",
     "G61.1", ["G0 X60"])
case("single-rapid-x80-router-g64", "router", "single",
     "the reference's G0 X80 in G64: a lone move planned with half the acceleration", "G64", ["G0 X80"])
case("single-rapid-x80-router-g61", "router", "single", "the reference's G0 X80 in exact path (G61)",
     "G61", ["G0 X80"])
case("single-rapid-diag-router", "router", "single",
     "a diagonal rapid: the trajectory maximum caps it (no sqrt(2) over 12 m/min)", "G61.1", ["G0 X100 Y60"])
case("single-rapid-xyz-router", "router", "single", "a rapid with Z: Z's velocity and acceleration limit it",
     "G61.1", ["G0 X40 Y30 Z-25"])
case("single-feed-x-mc", "machining_centre", "single", "a long fast feed move", "G61.1",
     ["G1 X300 F30000"])
case("single-feed-diag-hobby", "hobby_router", "single", "a diagonal feed move at 2400 mm/min", "G61.1",
     ["G1 X40 Y30 F2400"])
case("single-feed-z-hobby", "hobby_router", "single", "a Z plunge at 1200 mm/min (Z: 100 mm/s^2)",
     "G61.1", ["G1 Z-20 F1200"])
case("single-feed-z-over-axis-hobby", "hobby_router", "single",
     "a Z feed above Z's maximum velocity (F3000 on a 1500 mm/min axis)", "G61.1", ["G1 Z-15 F3000"])
case("single-rapid-c720-mc", "machining_centre", "single", "a rotary-only rapid of two turns of C",
     "G61.1", ["G0 C720"])
case("single-feed-c270-mc", "machining_centre", "single",
     "a rotary-only feed move: F in degrees per minute", "G61.1", ["G1 C270 F9000"])
case("single-feed-xc-mc", "machining_centre", "single",
     "a feed move of X and C together: timed by the linear length", "G61.1", ["G1 X60 C90 F6000"])
case("single-circle-r10-router", "router", "single",
     "one full circle R10 (G2, centre at X10) from the origin, exact stop", "G61.1",
     ["G2 X0 Y0 I10 J0 F3000"])
case("single-circle-g18-r5-mc", "machining_centre", "single",
     "one full circle R5 in G18 (XZ) at F6000", "G61.1", ["G18", "G2 X0 Z0 I0 K-5 F6000"])
case("single-feed-x-hobby-g64", "hobby_router", "single", "a lone feed move in G64: half acceleration",
     "G64", ["G1 X60 F3000"])
case("single-rapid-xy-mc-g64p", "machining_centre", "single", "a lone diagonal rapid in G64 P0.1",
     "G64 P0.1", ["G0 X200 Y100"])

# --- exact stop (G61.1) -------------------------------------------------------------------------
case("g611-square40-hobby", "hobby_router", "g61.1", "40 mm square at F2400, exact stop", "G61.1",
     ["F2400"] + square(40))
case("g611-square100-mc", "machining_centre", "g61.1", "100 mm square at F24000, exact stop", "G61.1",
     ["F24000"] + square(100))
case("g611-zigzag-router", "router", "g61.1", "a zigzag of six feed moves at F6000", "G61.1",
     ["F6000", "G1 X30 Y5", "G1 X0 Y10", "G1 X30 Y15", "G1 X0 Y20", "G1 X30 Y25", "G1 X0 Y30"])
case("g611-arcs-g17-router", "router", "g61.1", "semicircles of R1, R5 and R20 in G17 at F4000", "G61.1",
     ["F4000", "G2 X2 Y0 I1 J0", "G1 X10", "G3 X20 Y0 I5 J0", "G1 X25", "G2 X65 Y0 I20 J0"])
case("g611-arcs-g19-hobby", "hobby_router", "g61.1", "quarter and half arcs in G19 (YZ) at F1200",
     "G61.1", ["G19", "F1200", "G2 Y5 Z-5 J0 K-5", "G3 Y15 Z-5 J5 K0", "G1 Y20"])
case("g611-helix-r5-mc", "machining_centre", "g61.1", "a helix R5, two turns, 4 mm down, F6000", "G61.1",
     ["G0 X5", "G3 X5 Y0 Z-4 I-5 J0 P2 F6000"])
case("g611-dwell-router", "router", "g61.1", "feed moves with G4 dwells between them", "G61.1",
     ["F3000", "G1 X20", "G4 P0.25", "G1 Y20", "G4 P0.1", "G1 X0"])
case("g611-feedchange-hobby", "hobby_router", "g61.1", "three collinear moves at three feeds", "G61.1",
     ["G1 X20 F600", "G1 X40 F3000", "G1 X50 F1200"])
case("g611-g93-router", "router", "g61.1", "inverse time (G93): each block takes 1/F minutes at most",
     "G61.1", ["G93", "G1 X30 F120", "G1 Y30 F60", "G1 X0 Y0 F200"])
case("g611-g95-router", "router", "g61.1", "feed per revolution at S3000: F0.5 = 1500 mm/min", "G61.1",
     ["S3000 M3", "G95", "G1 X20 F0.5", "G1 Y10 F0.8", "G1 X0 F0.3"])
case("g611-chords36-r5-hobby", "hobby_router", "g61.1", "a circle R5 as 36 chords, exact stop at each",
     "G61.1", ["G0 X5 Y0", "F1500"] + chords(0, 0, 5, 36))

# --- exact path (G61) ---------------------------------------------------------------------------
case("g61-square40-hobby", "hobby_router", "g61", "40 mm square at F2400, exact path", "G61",
     ["F2400"] + square(40))
case("g61-square100-mc", "machining_centre", "g61", "100 mm square at F24000, exact path", "G61",
     ["F24000"] + square(100))
case("g61-chords36-r10-router", "router", "g61", "a circle R10 as 36 chords at F3000, exact path", "G61",
     ["G0 X10 Y0", "F3000"] + chords(0, 0, 10, 36))
case("g61-triangle-router", "router", "g61", "a triangle with acute corners at F6000", "G61",
     ["F6000", "G1 X60", "G1 X0 Y20", "G1 X0 Y0"])
case("g61-slot-router", "router", "g61", "a slot: lines joined by tangent semicircles R8 at F4000",
     "G61", ["G0 X0 Y-8", "F4000", "G1 X40", "G3 X40 Y8 I0 J8", "G1 X0", "G3 X0 Y-8 I0 J-8"])
case("g61-arcs-g18-mc", "machining_centre", "g61", "quarter arcs R10 in G18 (XZ) at F12000", "G61",
     ["G18", "F12000", "G2 X10 Z-10 I0 K-10", "G3 X20 Z-20 I10 K0", "G2 X30 Z-10 I0 K10"])
case("g61-rapid-feed-hobby", "hobby_router", "g61", "rapids and feeds in turn, exact path", "G61",
     ["G0 X10 Y10", "G0 Z-2", "G1 Z-5 F600", "G1 X40 F2400", "G1 Y30", "G0 Z5"])

# --- blending without a tolerance (G64) ----------------------------------------------------------
case("g64-square40-hobby", "hobby_router", "g64", "40 mm square at F2400, G64 without P", "G64",
     ["F2400"] + square(40))
case("g64-square100-mc", "machining_centre", "g64", "100 mm square at F24000, G64 without P", "G64",
     ["F24000"] + square(100))
case("g64-circle-r0.5-router", "router", "g64", "a full circle R0.5 at F3000: the arc's speed cap",
     "G64", ["G0 X0.5", "G2 X0.5 Y0 I-0.5 J0 F3000"])
case("g64-circle-r2-router", "router", "g64", "a full circle R2 at F3000", "G64",
     ["G0 X2", "G2 X2 Y0 I-2 J0 F3000"])
case("g64-circle-r50-router", "router", "g64", "a full circle R50 at F6000", "G64",
     ["G0 X50", "G3 X50 Y0 I-50 J0 F6000"])
case("g64-circle-r25-mc", "machining_centre", "g64", "a full circle R25 at F30000", "G64",
     ["G0 X25", "G3 X25 Y0 I-25 J0 F30000"])
case("g64-circle-r1-hobby", "hobby_router", "g64", "a full circle R1 at F3000", "G64",
     ["G0 X1", "G2 X1 Y0 I-1 J0 F3000"])
case("g64-chords72-r10-hobby", "hobby_router", "g64", "a circle R10 as 72 chords at F2400", "G64",
     ["G0 X10 Y0", "F2400"] + chords(0, 0, 10, 72))
case("g64-chords360-r20-router", "router", "g64",
     "a circle R20 as 360 chords (0.35 mm each) at F6000: short segments", "G64",
     ["G0 X20 Y0", "F6000"] + chords(0, 0, 20, 360))
case("g64-chords36-r10-mc", "machining_centre", "g64", "a circle R10 as 36 chords at F12000", "G64",
     ["G0 X10 Y0", "F12000"] + chords(0, 0, 10, 36))
case("g64-helix-r8-hobby", "hobby_router", "g64", "a helix R8, one turn, 2 mm down, F1500", "G64",
     ["G0 X8", "G3 X8 Y0 Z-2 I-8 J0 F1500"])
case("g64-arcs-g19-router", "router", "g64", "arcs in G19 (YZ): R3 and R10 at F3000", "G64",
     ["G19", "F3000", "G2 Y6 Z0 J3 K0", "G1 Y10", "G3 Y30 Z0 J10 K0"])
case("g64-helix-g18-mc", "machining_centre", "g64", "a full circle R6 in G18 with a Y move (helix)",
     "G64", ["G18", "G0 X6", "G2 X6 Z0 Y5 I-6 K0 F9000"])
case("g64-rapid-feed-router", "router", "g64", "a pocket-like sequence: rapids, plunge, feeds, retract",
     "G64", ["G0 X10 Y10", "G0 Z2", "G1 Z-1 F600", "G1 X50 F3000", "G1 Y30", "G1 X10", "G1 Y10",
             "G0 Z5", "G0 X0 Y0"])
case("g64-dwell-mc", "machining_centre", "g64", "feeds with a dwell between them, G64", "G64",
     ["F12000", "G1 X50", "G1 Y20", "G4 P0.3", "G1 X0", "G1 Y0"])
case("g64-feedchange-router", "router", "g64", "collinear and cornering moves at changing feeds", "G64",
     ["G1 X20 F2000", "G1 X40 F8000", "G1 X60 F1000", "G1 Y20 F6000", "G1 X0 F3000"])
case("g64-g93-mc", "machining_centre", "g64", "inverse time (G93) moves, G64", "G64",
     ["G93", "G1 X40 F300", "G1 Y40 F150", "G1 X0 Y0 F100"])
case("g64-g95-router", "router", "g64", "feed per revolution at S2000 (spindle loopback), G64", "G64",
     ["S2000 M3", "G95", "F1.5", "G1 X30", "G1 Y20", "G1 X0 F0.75", "G1 Y0"])
case("g64-rotary-mc", "machining_centre", "g64", "C moves alone and with X, G64", "G64",
     ["G0 C90", "G1 X20 F6000", "G1 C180 F12000", "G1 X40 C270 F6000", "G0 C0"])
case("g64-rounded-rect-hobby", "hobby_router", "g64",
     "a rectangle with tangent corner arcs R2, R5, R0.5, R10 at F2400", "G64",
     ["G0 X2 Y0", "F2400", "G1 X28", "G3 X30 Y2 I0 J2", "G1 Y15", "G3 X25 Y20 I-5 J0", "G1 X0.5",
      "G3 X0 Y19.5 I0 J-0.5", "G1 Y10", "G3 X10 Y0 I10 J0", "G1 X12"])

# --- blending within a tolerance (G64 P) ---------------------------------------------------------
case("g64p001-square60-router", "router", "g64p", "60 mm square at F4000 within 0.01 mm", "G64 P0.01",
     ["F4000"] + square(60))
case("g64p05-square40-hobby", "hobby_router", "g64p", "40 mm square at F2400 within 0.5 mm", "G64 P0.5",
     ["F2400"] + square(40))
case("g64p1-square100-mc", "machining_centre", "g64p", "100 mm square at F24000 within 1 mm",
     "G64 P1", ["F24000"] + square(100))
case("g64p01-chords36-r10-router", "router", "g64p",
     "a circle R10 as 36 chords at F3000 within 0.1 mm (more than the chords' sagitta)", "G64 P0.1",
     ["G0 X10 Y0", "F3000"] + chords(0, 0, 10, 36))
case("g64p002-chords72-r15-mc", "machining_centre", "g64p", "a circle R15 as 72 chords at F15000 within 0.02 mm",
     "G64 P0.02", ["G0 X15 Y0", "F15000"] + chords(0, 0, 15, 72))
case("g64p005-zigzag-hobby", "hobby_router", "g64p", "a zigzag of six moves at F3000 within 0.05 mm",
     "G64 P0.05", ["F3000", "G1 X30 Y5", "G1 X0 Y10", "G1 X30 Y15", "G1 X0 Y20", "G1 X30 Y25", "G1 X0 Y30"])
case("g64p02-arcs-router", "router", "g64p", "lines and arcs R1-R20 at F5000 within 0.2 mm", "G64 P0.2",
     ["F5000", "G1 X10", "G2 X12 Y0 I1 J0", "G1 X20 Y5", "G3 X30 Y5 I5 J0", "G1 X30 Y-10",
      "G2 X70 Y-10 I20 J0", "G1 Y10"])
case("g64p0005-square30-hobby", "hobby_router", "g64p", "30 mm square at F3000 within 0.005 mm",
     "G64 P0.005", ["F3000"] + square(30))

# --- lathe (XZC, G7 diameter mode, G18) ----------------------------------------------------------
LATHE = "G21 G90 G18 G7 G94"
case("lathe-face-g95", "lathe", "g64", "facing at S2500 with G95 F0.2 (spindle loopback), G7 diameters",
     "G64", ["S2500 M3", "G0 X40 Z1", "G95 F0.2", "G1 Z0", "G1 X0", "G0 Z2"], header=LATHE)
case("lathe-g96-face", "lathe", "g64",
     "facing at constant surface speed (G96 S150 D3000): the spindle speeds up towards the centre",
     "G64", ["G96 D3000 S150 M3", "G0 X40 Z0", "G95 F0.15", "G1 X2", "G0 Z2"], header=LATHE)
case("lathe-turn-g611", "lathe", "g61.1", "turning passes with G95 F0.25 at S3000, exact stop", "G61.1",
     ["S3000 M3", "G0 X30 Z1", "G95 F0.25", "G1 Z-20", "G1 X34", "G0 Z1", "G0 X28", "G1 Z-10"],
     header=LATHE)
case("lathe-c-moves", "lathe", "g64", "C positioning and C feed with X, G94 (lathe-flat style)", "G64",
     ["G0 X32 Z0 C0", "G1 C90 F7200", "G1 X30 C120 F200", "G1 X32 C150", "G0 C0"], header=LATHE)


# --- programs cutcalc writes (asked from the service) ---------------------------------------------
CUTCALC = [
    {"id": "cutcalc-main-time-router", "profile": "router", "category": "g64",
     "about": "cutcalc's pass program (POST /v1/main-time/program): 2 passes, rapids, plunges, feeds; "
              "no path mode named (G64); M5 M30 after the last move",
     "endpoint": "/v1/main-time/program",
     "request": {"cutter_diameter_mm": 20, "teeth": 4, "spindle_speed_rpm": 12000, "feed_per_tooth_mm": 0.05,
                 "length_mm": 40, "approach_mm": 2.0, "overrun_mm": 2.0,
                 "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90},
                 "exit": {"contour": "straight", "width_mm": 60, "angle_deg": 90}, "offset_mm": 0,
                 "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2.0, "depth_of_cut_mm": 1.0}}},
    {"id": "cutcalc-main-time-hobby", "profile": "hobby_router", "category": "g64",
     "about": "cutcalc's pass program with T3 M6 and coolant (M8) before the first move, one pass",
     "endpoint": "/v1/main-time/program",
     "request": {"cutter_diameter_mm": 10, "teeth": 2, "spindle_speed_rpm": 10000, "feed_per_tooth_mm": 0.06,
                 "length_mm": 25, "approach_mm": 2.0, "overrun_mm": 2.0,
                 "entry": {"contour": "straight", "width_mm": 30, "angle_deg": 90},
                 "exit": {"contour": "straight", "width_mm": 30, "angle_deg": 90}, "offset_mm": 0,
                 "allowance": {"width_mm": 10, "width_of_cut_mm": 10, "depth_mm": 1.0, "depth_of_cut_mm": 1.0},
                 "program": {"tool_number": 3, "coolant": "flood", "safe_z_mm": 5}}},
    {"id": "cutcalc-main-time-mc", "profile": "machining_centre", "category": "g64",
     "about": "cutcalc's pass program for convex-arc entry and exit at F6000 (entry at half feed)",
     "endpoint": "/v1/main-time/program",
     "request": {"cutter_diameter_mm": 20, "teeth": 4, "spindle_speed_rpm": 15000, "feed_per_tooth_mm": 0.1,
                 "entry_feed_factor": 0.5, "length_mm": 60, "approach_mm": 2.0, "overrun_mm": 2.0,
                 "entry": {"contour": "convex_arc", "radius_mm": 30},
                 "exit": {"contour": "convex_arc", "radius_mm": 30}, "offset_mm": 0,
                 "allowance": {"width_mm": 20, "width_of_cut_mm": 20, "depth_mm": 2.0, "depth_of_cut_mm": 2.0}}},
    {"id": "cutcalc-polygon-square-g95-router", "profile": "router", "category": "g64",
     "about": "cutcalc's polygon hole (POST /v1/polygon-hole/gcode): square a16, G95 at S300, small G3 arcs "
              "(R1-R2) with helical ramps, 2 layers x 3 loops",
     "endpoint": "/v1/polygon-hole/gcode",
     "request": {"faces": 4, "inscribed_diameter_mm": 16.0, "depth_mm": 0.2, "step_down_mm": 0.1,
                 "spindle_speed_rpm": 300}},
    {"id": "cutcalc-polygon-square-g95-mc", "profile": "machining_centre", "category": "g64",
     "about": "the same polygon-hole program on the machining centre",
     "endpoint": "/v1/polygon-hole/gcode",
     "request": {"faces": 4, "inscribed_diameter_mm": 16.0, "depth_mm": 0.2, "step_down_mm": 0.1,
                 "spindle_speed_rpm": 300},
     "unstable": True,
     "note": "1.211 s or 1.218 s from run to run: the blends right after the M3 sync depend on the phase "
             "between task and the servo thread. Compare with a tolerance of 10 ms."},
    {"id": "cutcalc-polygon-hexagon-caxis-mc", "profile": "machining_centre", "category": "g64",
     "about": "cutcalc's polygon hole with the spindle as C axis (G94, arcs with C words), hexagon d20, 30 rpm",
     "endpoint": "/v1/polygon-hole/gcode",
     "request": {"faces": 6, "inscribed_diameter_mm": 20.0, "depth_mm": 0.1, "step_down_mm": 0.1,
                 "spindle_speed_rpm": 30, "synchronization": "c_axis", "loops_per_layer": 1}},
    {"id": "cutcalc-polygon-triangle-g95-hobby", "profile": "hobby_router", "category": "g64",
     "about": "cutcalc's polygon hole, triangle d12, G95 at S60, one loop",
     "endpoint": "/v1/polygon-hole/gcode",
     "request": {"faces": 3, "inscribed_diameter_mm": 12.0, "depth_mm": 0.1, "step_down_mm": 0.1,
                 "spindle_speed_rpm": 60, "loops_per_layer": 1},
     "unstable": True,
     "note": "BIMODAL in LinuxCNC itself: 4.566 s or 4.641 s (+75 ms: the G95 plunge G1 Z0 and the first "
             "G3 end in a stop instead of blending). Task had read all 93 lines and queued one segment a "
             "millisecond in both; which way it goes depends on the phase between task and the servo "
             "thread after the M3 sync. Compare with a tolerance of 80 ms, or skip."},
    {"id": "cutcalc-polygon-pentagon-g95-router", "profile": "router", "category": "g64",
     "about": "cutcalc's polygon hole, pentagon d20, G95 at S100, arc-fit tolerance 0.01 mm",
     "endpoint": "/v1/polygon-hole/gcode",
     "request": {"faces": 5, "inscribed_diameter_mm": 20.0, "depth_mm": 0.1, "step_down_mm": 0.1,
                 "spindle_speed_rpm": 100, "tolerance_mm": 0.01}},
    {"id": "cutcalc-grooving-g97-lathe", "profile": "lathe", "category": "g64",
     "about": "cutcalc's grooving cycle (POST /v1/grooving/cycle): G7 G95 at G97 S800, a G4 dwell, "
              "M3 after the first rapid",
     "endpoint": "/v1/grooving/cycle",
     "request": {"groove_width_mm": 3, "start_diameter_mm": 50, "groove_left_z_mm": -12.5,
                 "feed_per_rev_mm": 0.1, "spindle_speed_rpm": 800, "nose_radius_mm": 0.2,
                 "minor_edge_angle_deg": 3, "groove_depth_mm": 0.3}},
    {"id": "cutcalc-grooving-g96-lathe", "profile": "lathe", "category": "g64",
     "about": "cutcalc's grooving cycle at constant surface speed (G96 D3000 S300), G95",
     "endpoint": "/v1/grooving/cycle",
     "request": {"groove_width_mm": 2, "start_diameter_mm": 40, "groove_depth_mm": 0.4,
                 "groove_left_z_mm": -12.5, "feed_per_rev_mm": 0.1, "cutting_speed_m_per_min": 300,
                 "max_spindle_rpm": 3000, "nose_radius_mm": 0.2, "minor_edge_angle_deg": 3},
     "unstable": True,
     "note": "0.923-0.930 s from run to run (M3 and a G4 dwell between moves: task's wall-clock timing). "
             "Compare with a tolerance of 10 ms."},
    {"id": "cutcalc-lathe-flat-lathe", "profile": "lathe", "category": "g64",
     "about": "cutcalc's lathe flat (POST /v1/lathe-flat): C positioning, then X+C steps in G93",
     "endpoint": "/v1/lathe-flat",
     "request": {"part_diameter_mm": 32, "flat_depth_mm": 1, "steps": 10, "feed_mm_per_min": 600}},
    {"id": "cutcalc-lathe-flat-2flats-lathe", "profile": "lathe", "category": "g64",
     "about": "cutcalc's lathe flat: two flats across 30 mm with a R6 tool, G93 steps, C indexing between",
     "endpoint": "/v1/lathe-flat",
     "request": {"part_diameter_mm": 32, "across_flats_mm": 30, "flats": 2, "tool_radius_mm": 6, "steps": 6,
                 "feed_mm_per_min": 1500}},
]


def fetch(base, endpoint, request):
    req = urllib.request.Request(base.rstrip("/") + endpoint, data=json.dumps(request).encode(),
                                 headers={"Content-Type": "application/json", "Accept": "text/plain"},
                                 method="POST")
    with urllib.request.urlopen(req, timeout=30) as answer:
        return answer.read().decode()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cutcalc", help="base URL of a running cutcalc, to (re)fetch its programs")
    args = parser.parse_args()
    os.makedirs(OUT, exist_ok=True)
    manifest_path = os.path.join(OUT, "manifest.json")
    entries = []
    for c in CASES:
        with open(os.path.join(OUT, c["id"] + ".ngc"), "w") as f:
            f.write(c["text"])
        entries.append({k: c[k] for k in ("id", "profile", "category", "about")} | {"source": "make_programs.py"})
    for c in CUTCALC:
        entry = {"id": c["id"], "profile": c["profile"], "category": c["category"], "about": c["about"],
                 "source": {"endpoint": c["endpoint"], "request": c["request"]}}
        for key in ("note", "unstable"):
            if c.get(key):
                entry[key] = c[key]
        if args.cutcalc:
            text = fetch(args.cutcalc, c["endpoint"], c["request"])
            with open(os.path.join(OUT, c["id"] + ".ngc"), "w") as f:
                f.write(text)
            entries.append(entry)
        elif os.path.exists(os.path.join(OUT, c["id"] + ".ngc")):
            entries.append(entry)  # the program as fetched earlier
        else:
            print(f"skipping {c['id']}: no --cutcalc and no earlier copy", file=sys.stderr)
    ids = [e["id"] for e in entries]
    assert len(ids) == len(set(ids)), "duplicate ids"
    manifest = {
        "about": "The oracle's programs: <id>.ngc beside this file, each timed on the named profile "
                 "by tools/oracle/record.py into tests/oracle/linuxcnc-times.json. Written by "
                 "tools/oracle/make_programs.py (cutcalc's own programs: asked from the service with "
                 "the request under source).",
        "profiles": PROFILES,
        "cases": entries,
    }
    with open(manifest_path, "w") as f:
        json.dump(manifest, f, indent=1)
        f.write("\n")
    print(f"{len(entries)} programs in {OUT}")


if __name__ == "__main__":
    main()
