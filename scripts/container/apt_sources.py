#!/usr/bin/python3
"""Reads the host's apt sources (one-line *.list and deb822 *.sources) and prints what
scripts/ci-container.sh needs to build a Debian base image from the same mirror:

  apt_sources.py mirror         the URI that serves the plain bookworm suite (for debootstrap)
  apt_sources.py mirror-keyring its Signed-By keyring file (empty: debootstrap's default)
  apt_sources.py sources-list   sources.list lines for the image: every enabled 'deb' entry of a
                                bookworm, bookworm-updates or bookworm-security suite
  apt_sources.py keyrings       the Signed-By keyring files those lines refer to (one a line)

Stdlib only. Exits 1 when no bookworm entry is found.
"""

import glob
import os
import sys

SUITES = ("bookworm", "bookworm-updates", "bookworm-security")
ROOT = os.environ.get("APT_SOURCES_ROOT", "/etc/apt")


def one_line_entries(path):
    with open(path, encoding="utf-8", errors="replace") as fh:
        for raw in fh:
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            words = line.split()
            if words[0] != "deb":
                continue
            words = words[1:]
            opts = {}
            if words and words[0].startswith("["):
                opt_words = []
                while words:
                    w = words.pop(0)
                    opt_words.append(w)
                    if w.endswith("]"):
                        break
                for o in " ".join(opt_words).strip("[] ").split():
                    if "=" in o:
                        k, v = o.split("=", 1)
                        opts[k.lower()] = v
            if len(words) < 2:
                continue
            yield words[0], words[1], words[2:] or ["main"], opts.get("signed-by")


def deb822_entries(path):
    with open(path, encoding="utf-8", errors="replace") as fh:
        text = fh.read()
    for stanza in text.split("\n\n"):
        fields, key = {}, None
        for raw in stanza.splitlines():
            if raw.startswith("#") or not raw.strip():
                continue
            if raw[0] in " \t" and key:
                fields[key] += "\n" + raw.strip()
                continue
            if ":" in raw:
                key, value = raw.split(":", 1)
                key = key.strip().lower()
                fields[key] = value.strip()
        if "deb" not in fields.get("types", "").split():
            continue
        if fields.get("enabled", "yes").lower() == "no":
            continue
        signed_by = fields.get("signed-by")
        if signed_by and ("BEGIN PGP" in signed_by or "\n" in signed_by):
            signed_by = None  # an inline key: the image's own debian-archive-keyring is used
        comps = fields.get("components", "main").split() or ["main"]
        for uri in fields.get("uris", "").split():
            for suite in fields.get("suites", "").split():
                yield uri, suite, comps, signed_by


def entries():
    files = [os.path.join(ROOT, "sources.list")]
    files += sorted(glob.glob(os.path.join(ROOT, "sources.list.d", "*.list")))
    files += sorted(glob.glob(os.path.join(ROOT, "sources.list.d", "*.sources")))
    seen = set()
    for path in files:
        if not os.path.isfile(path):
            continue
        reader = deb822_entries if path.endswith(".sources") else one_line_entries
        for uri, suite, comps, signed_by in reader(path):
            if suite not in SUITES:
                continue
            if signed_by and not os.path.isfile(signed_by):
                signed_by = None
            item = (uri.rstrip("/"), suite, tuple(comps), signed_by)
            if item not in seen:
                seen.add(item)
                yield item


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else ""
    found = list(entries())
    if not any(suite == "bookworm" for _, suite, _, _ in found):
        print(f"apt_sources: no enabled 'deb ... bookworm' entry under {ROOT}", file=sys.stderr)
        return 1
    if what == "mirror":
        print(next(uri for uri, suite, _, _ in found if suite == "bookworm"))
    elif what == "mirror-keyring":
        print(next(s or "" for _, suite, _, s in found if suite == "bookworm"))
    elif what == "sources-list":
        for uri, suite, comps, signed_by in found:
            opt = f"[signed-by={signed_by}] " if signed_by else ""
            print(f"deb {opt}{uri} {suite} {' '.join(comps)}")
    elif what == "keyrings":
        for k in sorted({s for _, _, _, s in found if s}):
            print(k)
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
