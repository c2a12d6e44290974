// Go peer for bench/http_bench.sh: one process, net/http and encoding/json only (no third-party
// modules). A line-by-line port of bench/peers/node_peer.js, so that Go does the same work as
// Node and cutcalc for two endpoints:
//
//	POST /v1/roughness/groove-wall   R2-R5 and Ra (R9-R12) of spec roughness.md
//	POST /v1/entry-length            E1, E2, E14 of spec entry-and-main-time.md, straight entry
//	                                 edge only, no exit
//
// i.e. Content-Type check (415), JSON parse (400), field validation collecting every error (422
// application/problem+json with JSON pointers; unknown fields rejected, in the order JavaScript's
// Object.keys gives them), the formula, and the answer with cutcalc's fields in cutcalc's order,
// numbers printed as JavaScript prints them and integral doubles as 12.0 like cutcalc. Not
// modelled (as in the Node peer): duplicate keys (the last one wins; cutcalc: 400), target_rz_um
// and bearing_points (rejected as unknown), the other contours, exit, length_mm. Parse error
// messages are Go's.
// Any other POST path: answers 200 with the request body as application/json (a bare echo).
// Same keep-alive policy as the Node peer: 5 s idle timeout, at most 10 000 requests a connection.
// The benchmark runs it with GOMAXPROCS=1 under taskset on the server CPU.
//
// usage: go_peer PORT [HOST]     prints "listening on HOST:PORT" once bound.
package main

import (
	"bytes"
	"context"
	"encoding/json"
	"errors"
	"fmt"
	"io"
	"math"
	"net"
	"net/http"
	"os"
	"os/signal"
	"sort"
	"strconv"
	"strings"
	"syscall"
	"time"
)

const (
	maxBodyBytes         = 64 * 1024            // cutcalc's default body limit (413 above it)
	radPerDeg            = 0.017453292519943295 // Math.PI / 180 in doubles, as cutcalc's kRadPerDeg
	umPerMm              = 1000.0
	maxRequestsPerSocket = 10000
)

// --- numbers as JavaScript prints them -----------------------------------------------------------

// jsNumber is Number.prototype.toString (ECMA-262 Number::toString): the shortest round-trip
// digits, plain notation for exponents -7 < n <= 21, else d.ddde+n.
func jsNumber(x float64) string {
	switch {
	case math.IsNaN(x):
		return "NaN"
	case math.IsInf(x, 1):
		return "Infinity"
	case math.IsInf(x, -1):
		return "-Infinity"
	case x == 0:
		return "0" // -0 too
	}
	sign := ""
	if x < 0 {
		sign, x = "-", -x
	}
	mantissa, exponent, _ := strings.Cut(strconv.FormatFloat(x, 'e', -1, 64), "e")
	digits := strings.Replace(mantissa, ".", "", 1)
	e, _ := strconv.Atoi(exponent)
	k, n := len(digits), e+1 // x = 0.digits * 10^n
	switch {
	case k <= n && n <= 21:
		return sign + digits + strings.Repeat("0", n-k)
	case 0 < n && n <= 21:
		return sign + digits[:n] + "." + digits[n:]
	case -6 < n && n <= 0:
		return sign + "0." + strings.Repeat("0", -n) + digits
	}
	expSign := "+"
	if n-1 < 0 {
		expSign = "-"
	}
	tail := expSign + strconv.Itoa(int(math.Abs(float64(n-1))))
	if k == 1 {
		return sign + digits + "e" + tail
	}
	return sign + digits[:1] + "." + digits[1:] + "e" + tail
}

// num prints a JSON number as cutcalc (nlohmann::json) prints a double: integral values with ".0".
func num(x float64) string {
	if !math.IsInf(x, 0) && x == math.Trunc(x) && math.Abs(x) < 1e21 {
		return jsNumber(x) + ".0"
	}
	return jsNumber(x)
}

// --- answers -------------------------------------------------------------------------------------

func send(w http.ResponseWriter, status int, contentType, text string) {
	h := w.Header()
	h.Set("Content-Type", contentType)
	h.Set("Content-Length", strconv.Itoa(len(text)))
	h.Set("X-Content-Type-Options", "nosniff")
	w.WriteHeader(status)
	io.WriteString(w, text) //nolint:errcheck // the client may be gone; nothing to do then
}

type fieldError struct {
	Pointer string `json:"pointer"`
	Detail  string `json:"detail"`
}

type problemBody struct {
	Type   string       `json:"type"`
	Title  string       `json:"title"`
	Status int          `json:"status"`
	Detail string       `json:"detail"`
	Errors []fieldError `json:"errors"`
}

// toJSON is JSON.stringify for the problem: no HTML escaping, no trailing newline.
func toJSON(v any) string {
	var out bytes.Buffer
	enc := json.NewEncoder(&out)
	enc.SetEscapeHTML(false)
	if err := enc.Encode(v); err != nil {
		panic(err) // only strings and ints: cannot fail
	}
	return strings.TrimSuffix(out.String(), "\n")
}

func problem(w http.ResponseWriter, status int, title, detail string, errs []fieldError) {
	if errs == nil {
		errs = []fieldError{}
	}
	send(w, status, "application/problem+json", toJSON(problemBody{"about:blank", title, status, detail, errs}))
}

// invalid answers 422 listing every field error; the detail names the first, as cutcalc's does.
func invalid(w http.ResponseWriter, errs []fieldError) {
	first := errs[0]
	more := ""
	if len(errs) > 1 {
		more = fmt.Sprintf(" (and %d more)", len(errs)-1)
	}
	field := strings.ReplaceAll(first.Pointer[1:], "/", ".")
	problem(w, 422, "Invalid input", field+" "+first.Detail+more, errs)
}

// --- request bodies ------------------------------------------------------------------------------

// body is a parsed request: values from encoding/json (json.Number for numbers, as JSON.parse keeps
// every number, even 1e400 as Infinity), and the raw text for the rare error path that needs the
// members' order (a Go map has none).
type body struct {
	raw  []byte
	root map[string]any
}

// memberOrder returns the names of the object at the given members' path in the order JavaScript's
// Object.keys lists them: array-index names ascending first, then the others as first written.
func (b *body) memberOrder(path []string) []string {
	names, err := objectNames(b.raw, path)
	if err != nil {
		return nil // cannot happen: the text parsed before
	}
	var indices, others []string
	seen := map[string]bool{}
	for _, name := range names {
		if seen[name] {
			continue
		}
		seen[name] = true
		if isArrayIndex(name) {
			indices = append(indices, name)
		} else {
			others = append(others, name)
		}
	}
	sort.Slice(indices, func(i, j int) bool {
		a, _ := strconv.ParseUint(indices[i], 10, 32)
		b, _ := strconv.ParseUint(indices[j], 10, 32)
		return a < b
	})
	return append(indices, others...)
}

// isArrayIndex: a canonical decimal integer below 2^32 - 1 (ECMA-262 array index).
func isArrayIndex(name string) bool {
	if name == "" || (len(name) > 1 && name[0] == '0') {
		return false
	}
	v, err := strconv.ParseUint(name, 10, 32)
	return err == nil && v < math.MaxUint32
}

// objectNames returns the member names of the object at path inside the JSON text (the text's
// own for an empty path), in the order written, duplicates included.
func objectNames(text []byte, path []string) ([]string, error) {
	dec := json.NewDecoder(bytes.NewReader(text))
	if token, err := dec.Token(); err != nil || token != json.Delim('{') {
		return nil, errors.New("not an object")
	}
	var names []string
	for dec.More() {
		token, err := dec.Token()
		if err != nil {
			return nil, err
		}
		name, _ := token.(string)
		var value json.RawMessage
		if err := dec.Decode(&value); err != nil {
			return nil, err
		}
		if len(path) == 0 {
			names = append(names, name)
		} else if name == path[0] {
			if inner, err := objectNames(value, path[1:]); err == nil {
				names = inner // the last duplicate wins, as in JSON.parse
			}
		}
	}
	return names, nil
}

// Field checks; each appends {pointer, detail} to errs and returns the value (or the fallback).
type checker struct {
	body *body
	obj  map[string]any
	path []string // member names from the root, for memberOrder
	base string   // the JSON pointer of obj
	errs *[]fieldError
}

func (c checker) fail(name, detail string) {
	*c.errs = append(*c.errs, fieldError{c.base + "/" + name, detail})
}

type numberRule struct {
	required bool
	fallback float64
	ok       func(float64) bool
	rule     string
}

func (c checker) number(name string, r numberRule) float64 {
	raw, present := c.obj[name]
	if !present {
		if r.required {
			c.fail(name, "is required")
		}
		return r.fallback
	}
	text, isNumber := raw.(json.Number)
	if !isNumber {
		c.fail(name, "must be a number")
		return r.fallback
	}
	// Out of range: +-Inf (as JSON.parse gives) or 0 for an underflow, with ErrRange.
	v, err := strconv.ParseFloat(string(text), 64)
	if err != nil && !errors.Is(err, strconv.ErrRange) {
		c.fail(name, "must be a number")
	} else if math.IsInf(v, 0) || math.IsNaN(v) {
		c.fail(name, "must be a finite number")
	} else if r.ok != nil && !r.ok(v) {
		c.fail(name, r.rule)
	}
	return v
}

func (c checker) unknown(known ...string) {
	if len(c.obj) == 0 {
		return
	}
	extra := false
	for name := range c.obj {
		if !contains(known, name) {
			extra = true
			break
		}
	}
	if !extra { // the hot path: no need for the members' order
		return
	}
	for _, name := range c.body.memberOrder(c.path) {
		if !contains(known, name) {
			c.fail(name, "is not a known field")
		}
	}
}

func contains(list []string, s string) bool {
	for _, item := range list {
		if item == s {
			return true
		}
	}
	return false
}

func positive(v float64) bool { return v > 0 }

// --- POST /v1/roughness/groove-wall (R2-R5; Ra by R9-R12) ---------------------------------------

// sqrtProduct is sqrt(a) sqrt(b) rather than sqrt(a b): the product could overflow for huge lengths.
func sqrtProduct(a, b float64) float64 {
	return math.Sqrt(math.Max(a, 0)) * math.Sqrt(math.Max(b, 0))
}

// edgeAngle: sin, cos, tan of phi1 and 2 sin^2(phi1/2) (1 - cos(phi1) without cancellation).
type edgeAngle struct{ sin, cos, tan, twoSinSqHalf float64 }

func newEdgeAngle(phi1 float64) edgeAngle {
	sinHalf := math.Sin(0.5 * phi1)
	return edgeAngle{math.Sin(phi1), math.Cos(phi1), math.Tan(phi1), 2 * sinHalf * sinHalf}
}

// noseArcAbscissa: where a nose arc reaches height y <= rho, u = sqrt(y (2 rho - y)).
func noseArcAbscissa(y, rho float64) float64 {
	return math.Sqrt(math.Max(y, 0)) * math.Sqrt(math.Max(2*rho-y, 0))
}

// profile is one pitch (phi1 > 0): the crest Rz, its branch, where the left side ends (uC) and its
// height there (yLeftEnd: Rz, or rho where the profile jumps to Rz).
type profile struct {
	S, rho       float64
	a            edgeAngle
	Rz           float64
	branch       string
	uC, yLeftEnd float64
}

// pitchProfile is R2-R5 and R9.
func pitchProfile(S, rho float64, a edgeAngle) profile {
	SAB := 2 * rho * a.sin // R2
	SBC := rho + rho/a.sin
	if S <= SAB { // R3
		h := 0.5 * S
		Rz := h * (h / (rho + sqrtProduct(rho-h, rho+h)))
		return profile{S, rho, a, Rz, "nose_arc", S / 2, Rz}
	}
	if S <= SBC { // R4, the bracket multiplied by its conjugate
		Ssin := S * a.sin
		root := sqrtProduct(Ssin, 2*rho-Ssin)
		bracket := S * ((S - SAB) / (S*a.cos + root))
		Rz := rho*a.twoSinSqHalf + a.sin*bracket
		return profile{S, rho, a, Rz, "nose_arc_and_minor_edge", math.Min(noseArcAbscissa(Rz, rho), rho), Rz}
	}
	Rz := rho + (S-SBC)*a.tan // R5
	return profile{S, rho, a, Rz, "minor_edge_and_main_edge", rho, rho}
}

// thetaMinusSine is th - sin(th): its series below 0.1 rad, where the difference would lose its
// digits (R11).
func thetaMinusSine(th float64) float64 {
	if th < 0.1 {
		th2 := th * th
		return th * th2 * (1.0/6 - th2*(1.0/120-th2*(1.0/5040-th2/362880)))
	}
	return th - math.Sin(th)
}

// noseArcArea is R11: the area under a nose arc over [0, x].
func noseArcArea(x, rho float64) float64 {
	th := math.Asin(math.Min(math.Max(x/rho, 0), 1))
	sinHalf := math.Sin(th / 2)
	return rho * rho * (math.Sin(th)*sinHalf*sinHalf - thetaMinusSine(th)/2)
}

// minorEdgeOffset: the minor edge is y = v tan(phi1) - minorEdgeOffset (R9).
func (p profile) minorEdgeOffset() float64 {
	return p.rho * p.a.twoSinSqHalf / p.a.cos
}

// rightSideArea is R11's I_R(v): the area under the right side (trailing arc, then the minor edge).
func (p profile) rightSideArea(v float64) float64 {
	vA := p.rho * p.a.sin
	if v <= vA {
		return noseArcArea(v, p.rho)
	}
	return noseArcArea(vA, p.rho) + p.a.tan*(v-vA)*(v+vA)/2 - p.minorEdgeOffset()*(v-vA)
}

// rightSideAbscissa: where the right side reaches height y; the arc below y_a = 2 rho
// sin^2(phi1/2), the edge above.
func (p profile) rightSideAbscissa(y float64) float64 {
	yA := p.rho * p.a.twoSinSqHalf
	v := (y + p.minorEdgeOffset()) / p.a.tan
	if y <= yA {
		v = noseArcAbscissa(y, p.rho)
	}
	return math.Min(v, p.S-p.uC)
}

// arithmeticMeanDeviation is R10 and R12: Ra in mm, twice the area between the mean line and the
// profile below it, on the profile scaled by a power of two near max(S, rho) (exact) so that no
// area overflows.
func arithmeticMeanDeviation(S, rho float64, a edgeAngle) float64 {
	_, exp := math.Frexp(math.Max(S, rho)) // max = m 2^exp, m in [0.5, 1): C's ilogb is exp - 1
	scale := math.Ldexp(1, exp-1)
	p := pitchProfile(S/scale, rho/scale, a)
	ybar := (noseArcArea(p.uC, p.rho) + p.rightSideArea(p.S-p.uC)) / p.S // R10
	uL := p.uC
	if ybar < p.yLeftEnd {
		uL = math.Min(noseArcAbscissa(ybar, p.rho), p.uC)
	}
	vR := p.rightSideAbscissa(ybar)
	below := ybar*(uL+vR) - noseArcArea(uL, p.rho) - p.rightSideArea(vR)
	return math.Max(2*below/p.S, 0) * scale
}

func grooveWall(S, rho, phi1Deg float64) (rzMm, raMm float64, branch string) {
	phi1 := phi1Deg * radPerDeg
	if phi1 == 0 { // R4 with phi1 = 0: the minor edge is the wall itself; the profile is flat
		return 0, 0, "nose_arc_and_minor_edge"
	}
	a := newEdgeAngle(phi1)
	p := pitchProfile(S, rho, a)
	return p.Rz, arithmeticMeanDeviation(S, rho, a), p.branch
}

func handleGrooveWall(w http.ResponseWriter, b *body) {
	var errs []fieldError
	c := checker{b, b.root, nil, "", &errs}
	mustBePositive := numberRule{required: true, ok: positive, rule: "must be > 0"}
	S := c.number("feed_mm", mustBePositive)
	rho := c.number("nose_radius_mm", mustBePositive)
	phi1 := c.number("minor_edge_angle_deg", numberRule{
		required: true, ok: func(v float64) bool { return v >= 0 && v < 90 }, rule: "must be in [0, 90)",
	})
	c.unknown("feed_mm", "nose_radius_mm", "minor_edge_angle_deg")
	if len(errs) > 0 {
		invalid(w, errs)
		return
	}
	rzMm, raMm, branch := grooveWall(S, rho, phi1)
	rz, ra := rzMm*umPerMm, raMm*umPerMm
	if math.IsInf(rz, 0) || math.IsNaN(rz) || math.IsInf(ra, 0) || math.IsNaN(ra) {
		detail := "the crest height exceeds the range of a double"
		problem(w, 422, "Input impossible for the model", detail, []fieldError{{"", detail}})
		return
	}
	send(w, 200, "application/json", `{"branch":"`+branch+`","ra_um":`+num(ra)+`,"rz_um":`+num(rz)+`}`)
}

// --- POST /v1/entry-length, straight entry edge (E1, E2, E14) ------------------------------------

// halfChord is E1: s(u) = sqrt((r - u)(r + u)), clamped at 0 (tangency stays exact).
func halfChord(r, u float64) float64 {
	p := (r - u) * (r + u)
	if p > 0 {
		return math.Sqrt(p)
	}
	return 0
}

type entry struct{ Lvr1, Lvr, Xn, Yn, W float64 }

func entryLength(D, K, Lpod, B, alphaDeg float64) (entry, bool) {
	h := B / 2 // E3
	r := D / 2 // E1
	lowReach := K - r
	highReach := K + r
	a := math.Max(lowReach, -h) // E2
	b := math.Min(highReach, h)
	W := b - a
	if !(W > 0) {
		return entry{}, false
	}
	// cot(90) = 0 and cos(90) = 0 exactly (cos(pi/2) is not 0 in doubles).
	cot, cos := 0.0, 0.0
	if alphaDeg != 90 {
		alpha := alphaDeg * radPerDeg
		cos = math.Cos(alpha)
		cot = cos / math.Sin(alpha)
	}
	// E14 g(y) = s(y - K) - (y + h) cot(alpha), with u = y - K exact at the band ends (-r or +r
	// where the band ends on the cutter's edge, -h - K or h - K on the workpiece's edge).
	g := func(y, u float64) float64 { return halfChord(r, u) - (y+h)*cot }
	uA := -h - K
	if lowReach >= -h {
		uA = -r
	}
	uB := h - K
	if highReach <= h {
		uB = r
	}
	gA := g(a, uA)
	gB := g(b, uB)
	uStar := -r * cos // y* - K, y* = clamp(K - r cos(alpha), a, b)
	var gStar float64
	switch {
	case uStar <= uA:
		gStar = gA
	case uStar >= uB:
		gStar = gB
	default:
		gStar = g(K+uStar, uStar)
	}
	Xn := Lpod + gStar
	Lvr1 := gStar - math.Min(gA, gB)
	return entry{Lvr1: Lvr1, Lvr: Lpod + Lvr1, Xn: Xn, Yn: h + K, W: W}, true
}

func handleEntryLength(w http.ResponseWriter, b *body) {
	var errs []fieldError
	c := checker{b, b.root, nil, "", &errs}
	D := c.number("cutter_diameter_mm", numberRule{required: true, ok: positive, rule: "must be > 0"})
	K := c.number("offset_mm", numberRule{fallback: 0})
	Lpod := c.number("approach_mm", numberRule{
		fallback: 2, ok: func(v float64) bool { return v >= 0 }, rule: "must be >= 0",
	})
	c.unknown("cutter_diameter_mm", "offset_mm", "approach_mm", "entry")
	var B, alpha float64
	given, present := b.root["entry"]
	if !present {
		c.fail("entry", "is required")
	} else if obj, isObject := given.(map[string]any); !isObject {
		c.fail("entry", "must be an object")
	} else {
		e := checker{b, obj, []string{"entry"}, "/entry", &errs}
		if contour, present := obj["contour"]; !present {
			e.fail("contour", "is required")
		} else if contour != "straight" {
			e.fail("contour", `must be "straight" (the only contour this peer models)`)
		}
		B = e.number("width_mm", numberRule{required: true, ok: positive, rule: "must be > 0"})
		alpha = e.number("angle_deg", numberRule{
			fallback: 90, ok: func(v float64) bool { return v > 0 && v < 180 }, rule: "must be in (0, 180)",
		})
		e.unknown("contour", "width_mm", "angle_deg")
	}
	if len(errs) > 0 {
		invalid(w, errs)
		return
	}
	out, contact := entryLength(D, K, Lpod, B, alpha)
	if !contact {
		detail := "the tool does not reach the workpiece: there is no contact"
		problem(w, 422, "Input impossible for the model", detail, []fieldError{{"", detail}})
		return
	}
	send(w, 200, "application/json",
		`{"engagement_length_mm":`+num(out.Lvr1)+`,"entry_length_mm":`+num(out.Lvr)+`,`+
			`"start":{"x_mm":`+num(out.Xn)+`,"y_mm":`+num(out.Yn)+`},"steady_width_mm":`+num(out.W)+`}`)
}

// --- HTTP ----------------------------------------------------------------------------------------

var routes = map[string]func(http.ResponseWriter, *body){
	"/v1/roughness/groove-wall": handleGrooveWall,
	"/v1/entry-length":          handleEntryLength,
}

func isJSON(contentType string, present bool) bool {
	if !present {
		return false
	}
	media, _, _ := strings.Cut(contentType, ";")
	return strings.ToLower(strings.TrimSpace(media)) == "application/json"
}

func answer(w http.ResponseWriter, r *http.Request, raw []byte) {
	handler, known := routes[r.RequestURI] // the raw target, as Node's req.url
	if !known {                            // bare echo
		w.Header().Set("Content-Type", "application/json")
		w.Header().Set("Content-Length", strconv.Itoa(len(raw)))
		w.WriteHeader(200)
		w.Write(raw) //nolint:errcheck
		return
	}
	// The first Content-Type, as Node keeps (it drops duplicates).
	if !isJSON(r.Header.Get("Content-Type"), len(r.Header.Values("Content-Type")) > 0) {
		problem(w, 415, "Unsupported media type", "send the request body as application/json", nil)
		return
	}
	dec := json.NewDecoder(bytes.NewReader(raw))
	dec.UseNumber()
	var parsed any
	err := dec.Decode(&parsed)
	if err == nil {
		if _, after := dec.Token(); after != io.EOF {
			err = errors.New("unexpected data after the JSON value")
		}
	}
	if err != nil {
		problem(w, 400, "Malformed JSON", "the request body is not valid JSON: "+err.Error(), nil)
		return
	}
	root, isObject := parsed.(map[string]any)
	if !isObject {
		detail := "the request body must be a JSON object"
		problem(w, 422, "Invalid input", detail, []fieldError{{"", detail}})
		return
	}
	handler(w, &body{raw: raw, root: root})
}

type requestCountKey struct{}

func serve(w http.ResponseWriter, r *http.Request) {
	if count, ok := r.Context().Value(requestCountKey{}).(*int); ok {
		*count++ // one goroutine serves a connection's requests in turn: no race
		if *count >= maxRequestsPerSocket {
			w.Header().Set("Connection", "close")
		}
	}
	if r.Method != http.MethodPost {
		w.Header().Set("Content-Length", "0")
		w.WriteHeader(404)
		return
	}
	raw, err := io.ReadAll(io.LimitReader(r.Body, maxBodyBytes+1))
	if err != nil {
		return // the client went away mid-body
	}
	if len(raw) > maxBodyBytes {
		problem(w, 413, "Payload too large", fmt.Sprintf("the request body exceeds %d bytes", maxBodyBytes), nil)
		return
	}
	answer(w, r, raw)
}

func main() {
	if len(os.Args) < 2 {
		usage()
	}
	port, err := strconv.Atoi(os.Args[1])
	if err != nil || port < 0 || port > 65535 {
		usage()
	}
	host := "127.0.0.1"
	if len(os.Args) > 2 {
		host = os.Args[2]
	}
	listener, err := net.Listen("tcp", net.JoinHostPort(host, strconv.Itoa(port)))
	if err != nil {
		fmt.Fprintln(os.Stderr, "go_peer:", err)
		os.Exit(1)
	}
	server := &http.Server{
		Handler:           http.HandlerFunc(serve),
		IdleTimeout:       5 * time.Second,  // Node's keepAliveTimeout in node_peer.js
		ReadHeaderTimeout: 60 * time.Second, // Node's default headersTimeout
		ConnContext: func(ctx context.Context, _ net.Conn) context.Context {
			return context.WithValue(ctx, requestCountKey{}, new(int))
		},
	}
	stop := make(chan os.Signal, 1)
	signal.Notify(stop, syscall.SIGTERM, syscall.SIGINT)
	go func() {
		<-stop
		server.Close() //nolint:errcheck
		os.Exit(0)
	}()
	fmt.Printf("listening on %s:%d\n", host, listener.Addr().(*net.TCPAddr).Port)
	if err := server.Serve(listener); err != nil && !errors.Is(err, http.ErrServerClosed) {
		fmt.Fprintln(os.Stderr, "go_peer:", err)
		os.Exit(1)
	}
}

func usage() {
	fmt.Fprintln(os.Stderr, "usage: go_peer PORT [HOST]")
	os.Exit(2)
}
