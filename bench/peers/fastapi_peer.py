#!/usr/bin/python3
"""FastAPI/uvicorn peer for bench/http_bench.sh: the same two endpoints as bench/peers/node_peer.js.

  POST /v1/roughness/groove-wall   R2-R5 and Ra (R9-R12) of spec roughness.md (port of cutcalc's
                                   domain/roughness/crest_branches.cpp, pitch_profile.cpp and
                                   groove_wall.cpp)
  POST /v1/entry-length            E1, E2, E14 of spec entry-and-main-time.md, straight entry edge
                                   only, no exit

pydantic 1.10 models with cutcalc's constraints (required finite numbers, ranges, extra fields
forbidden; FastAPI's own 422 for a field error, 400 for malformed JSON), 415 for a content type
other than application/json, a 422 problem+json for no contact, and the answer with cutcalc's fields
in cutcalc's order. Any other POST path answers 200 with the request body (a bare echo).

Runs on Debian's interpreter with Debian's packages (python3-fastapi 0.92, python3-uvicorn 0.17.6,
pydantic 1.10): one uvicorn worker, one process.
usage: /usr/bin/python3 fastapi_peer.py PORT [HOST]
"""

import math
import sys

try:
    import uvicorn
    from fastapi import Depends, FastAPI, HTTPException, Request, Response
    from fastapi.responses import JSONResponse
    from pydantic import BaseModel, Extra, confloat, validator
    from typing import Literal
except ImportError as error:
    sys.exit(f"fastapi_peer.py: {error} (interpreter {sys.executable}); "
             "on Debian: apt-get install python3-fastapi python3-uvicorn")

RAD_PER_DEG = math.pi / 180.0  # 0.017453292519943295, as cutcalc's kRadPerDeg
UM_PER_MM = 1000.0


def finite_number(value):
    """A JSON number (not a string or a boolean) that is finite; runs before pydantic's coercion."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError("must be a number")
    try:
        value = float(value)
    except OverflowError:
        raise ValueError("must be a finite number") from None
    if not math.isfinite(value):
        raise ValueError("must be a finite number")
    return value


class Strict(BaseModel):
    class Config:
        extra = Extra.forbid


class GrooveWallRequest(Strict):
    feed_mm: confloat(gt=0)
    nose_radius_mm: confloat(gt=0)
    minor_edge_angle_deg: confloat(ge=0, lt=90)

    _numbers = validator("feed_mm", "nose_radius_mm", "minor_edge_angle_deg", pre=True,
                         allow_reuse=True)(finite_number)


class GrooveWallAnswer(BaseModel):
    branch: str
    ra_um: float
    rz_um: float


class StraightEntry(Strict):
    contour: Literal["straight"]
    width_mm: confloat(gt=0)
    angle_deg: confloat(gt=0, lt=180) = 90.0

    _numbers = validator("width_mm", "angle_deg", pre=True, allow_reuse=True)(finite_number)


class EntryLengthRequest(Strict):
    cutter_diameter_mm: confloat(gt=0)
    offset_mm: float = 0.0
    approach_mm: confloat(ge=0) = 2.0
    entry: StraightEntry

    _numbers = validator("cutter_diameter_mm", "offset_mm", "approach_mm", pre=True,
                         allow_reuse=True)(finite_number)


class Point(BaseModel):
    x_mm: float
    y_mm: float


class EntryLengthAnswer(BaseModel):
    engagement_length_mm: float
    entry_length_mm: float
    start: Point
    steady_width_mm: float


def sqrt_product(a, b):
    """sqrt(a) sqrt(b) rather than sqrt(a b): the product could overflow for huge lengths."""
    return math.sqrt(max(a, 0.0)) * math.sqrt(max(b, 0.0))


class EdgeAngle:
    """sin, cos, tan of phi1 and 2 sin^2(phi1/2) (1 - cos(phi1) without cancellation)."""

    def __init__(self, phi1):
        sin_half = math.sin(0.5 * phi1)
        self.sin, self.cos, self.tan = math.sin(phi1), math.cos(phi1), math.tan(phi1)
        self.two_sin_sq_half = 2.0 * sin_half * sin_half


def nose_arc_abscissa(y, rho):
    """Where a nose arc reaches height y <= rho: u = sqrt(y (2 rho - y))."""
    return math.sqrt(max(y, 0.0)) * math.sqrt(max(2.0 * rho - y, 0.0))


class PitchProfile:
    """R2-R5 and R9 (phi1 > 0): the crest Rz of one pitch, its branch, where the left side ends
    (u_c) and its height there (y_left_end: Rz, or rho where the profile jumps to Rz)."""

    def __init__(self, S, rho, a):
        self.S, self.rho, self.a = S, rho, a
        S_AB = 2.0 * rho * a.sin  # R2
        S_BC = rho + rho / a.sin
        if S <= S_AB:  # R3
            h = 0.5 * S
            self.Rz = h * (h / (rho + sqrt_product(rho - h, rho + h)))
            self.branch, self.u_c, self.y_left_end = "nose_arc", S / 2.0, self.Rz
        elif S <= S_BC:  # R4, the bracket multiplied by its conjugate
            S_sin = S * a.sin
            root = sqrt_product(S_sin, 2.0 * rho - S_sin)
            bracket = S * ((S - S_AB) / (S * a.cos + root))
            self.Rz = rho * a.two_sin_sq_half + a.sin * bracket
            self.branch = "nose_arc_and_minor_edge"
            self.u_c, self.y_left_end = min(nose_arc_abscissa(self.Rz, rho), rho), self.Rz
        else:  # R5
            self.Rz = rho + (S - S_BC) * a.tan
            self.branch, self.u_c, self.y_left_end = "minor_edge_and_main_edge", rho, rho

    def minor_edge_offset(self):
        """The minor edge is y = v tan(phi1) - minor_edge_offset (R9)."""
        return self.rho * self.a.two_sin_sq_half / self.a.cos

    def right_side_area(self, v):
        """R11's I_R(v): the area under the right side (trailing arc, then the minor edge)."""
        v_a = self.rho * self.a.sin
        if v <= v_a:
            return nose_arc_area(v, self.rho)
        return (nose_arc_area(v_a, self.rho) + self.a.tan * (v - v_a) * (v + v_a) / 2.0
                - self.minor_edge_offset() * (v - v_a))

    def right_side_abscissa(self, y):
        """Where the right side reaches height y: the arc below y_a = 2 rho sin^2(phi1/2), the
        edge above."""
        y_a = self.rho * self.a.two_sin_sq_half
        v = nose_arc_abscissa(y, self.rho) if y <= y_a else (y + self.minor_edge_offset()) / self.a.tan
        return min(v, self.S - self.u_c)


def theta_minus_sine(th):
    """th - sin(th): its series below 0.1 rad, where the difference would lose its digits (R11)."""
    if th < 0.1:
        th2 = th * th
        return th * th2 * (1.0 / 6.0 - th2 * (1.0 / 120.0 - th2 * (1.0 / 5040.0 - th2 / 362880.0)))
    return th - math.sin(th)


def nose_arc_area(x, rho):
    """R11: the area under a nose arc over [0, x]."""
    th = math.asin(min(max(x / rho, 0.0), 1.0))
    sin_half = math.sin(th / 2.0)
    return rho * rho * (math.sin(th) * sin_half * sin_half - theta_minus_sine(th) / 2.0)


def arithmetic_mean_deviation(S, rho, a):
    """R10, R12: Ra in mm, twice the area between the mean line and the profile below it, on the
    profile scaled by a power of two near max(S, rho) (exact) so that no area overflows."""
    scale = math.ldexp(1.0, math.frexp(max(S, rho))[1] - 1)  # 2^ilogb(max(S, rho))
    p = PitchProfile(S / scale, rho / scale, a)
    ybar = (nose_arc_area(p.u_c, p.rho) + p.right_side_area(p.S - p.u_c)) / p.S  # R10
    u_l = min(nose_arc_abscissa(ybar, p.rho), p.u_c) if ybar < p.y_left_end else p.u_c
    v_r = p.right_side_abscissa(ybar)
    below = ybar * (u_l + v_r) - nose_arc_area(u_l, p.rho) - p.right_side_area(v_r)
    return max(2.0 * below / p.S, 0.0) * scale


def groove_wall(S, rho, phi1_deg):
    """R2-R5, R9-R12: (Rz in mm, Ra in mm, branch)."""
    phi1 = phi1_deg * RAD_PER_DEG
    if phi1 == 0.0:  # R4 with phi1 = 0: the minor edge is the wall itself; the profile is flat
        return 0.0, 0.0, "nose_arc_and_minor_edge"
    a = EdgeAngle(phi1)
    p = PitchProfile(S, rho, a)
    return p.Rz, arithmetic_mean_deviation(S, rho, a), p.branch


def half_chord(r, u):
    """E1: s(u) = sqrt((r - u)(r + u)), clamped at 0."""
    p = (r - u) * (r + u)
    return math.sqrt(p) if p > 0.0 else 0.0


def entry_length(D, K, L_pod, B, alpha_deg):
    """E1, E2, E14 for a straight entry edge; None when there is no contact."""
    h, r = B / 2.0, D / 2.0
    low_reach, high_reach = K - r, K + r
    a, b = max(low_reach, -h), min(high_reach, h)  # E2
    W = b - a
    if not W > 0.0:
        return None
    cot = cos = 0.0  # cot(90) = cos(90) = 0 exactly
    if alpha_deg != 90.0:
        alpha = alpha_deg * RAD_PER_DEG
        cos = math.cos(alpha)
        cot = cos / math.sin(alpha)

    def g(y, u):  # E14, u = y - K exact at the band ends
        return half_chord(r, u) - (y + h) * cot

    u_a = -r if low_reach >= -h else -h - K
    u_b = r if high_reach <= h else h - K
    g_a, g_b = g(a, u_a), g(b, u_b)
    u_star = -r * cos  # y* - K, y* = clamp(K - r cos(alpha), a, b)
    g_star = g_a if u_star <= u_a else g_b if u_star >= u_b else g(K + u_star, u_star)
    L_vr1 = g_star - min(g_a, g_b)
    return EntryLengthAnswer(engagement_length_mm=L_vr1, entry_length_mm=L_pod + L_vr1,
                             start=Point(x_mm=L_pod + g_star, y_mm=h + K), steady_width_mm=W)


def problem(status, title, detail, errors):
    return JSONResponse(status_code=status, media_type="application/problem+json",
                        content={"type": "about:blank", "title": title, "status": status,
                                 "detail": detail, "errors": errors})


def json_only(request: Request):
    media = request.headers.get("content-type", "").split(";", 1)[0].strip().lower()
    if media != "application/json":
        raise HTTPException(status_code=415, detail="send the request body as application/json")


app = FastAPI(openapi_url=None, docs_url=None, redoc_url=None)


@app.post("/v1/roughness/groove-wall", response_model=GrooveWallAnswer,
          dependencies=[Depends(json_only)])
async def groove_wall_endpoint(body: GrooveWallRequest):
    rz_mm, ra_mm, branch = groove_wall(body.feed_mm, body.nose_radius_mm, body.minor_edge_angle_deg)
    rz_um, ra_um = rz_mm * UM_PER_MM, ra_mm * UM_PER_MM
    if not (math.isfinite(rz_um) and math.isfinite(ra_um)):
        detail = "the crest height exceeds the range of a double"
        return problem(422, "Input impossible for the model", detail, [{"pointer": "", "detail": detail}])
    return GrooveWallAnswer(branch=branch, ra_um=ra_um, rz_um=rz_um)


@app.post("/v1/entry-length", response_model=EntryLengthAnswer, dependencies=[Depends(json_only)])
async def entry_length_endpoint(body: EntryLengthRequest):
    answer = entry_length(body.cutter_diameter_mm, body.offset_mm, body.approach_mm,
                          body.entry.width_mm, body.entry.angle_deg)
    if answer is None:
        detail = "the tool does not reach the workpiece: there is no contact"
        return problem(422, "Input impossible for the model", detail, [{"pointer": "", "detail": detail}])
    return answer


@app.post("/{path:path}")
async def echo(request: Request):
    return Response(await request.body(), media_type="application/json")


def main():
    if len(sys.argv) not in (2, 3) or not sys.argv[1].isdigit() or int(sys.argv[1]) > 65535:
        sys.exit("usage: fastapi_peer.py PORT [HOST]")
    port = int(sys.argv[1])
    host = sys.argv[2] if len(sys.argv) == 3 else "127.0.0.1"
    # uvicorn's keep-alive timeout is 5 s by default, as cutcalc's.
    uvicorn.run(app, host=host, port=port, workers=1, log_level="warning", access_log=False)


if __name__ == "__main__":
    main()
