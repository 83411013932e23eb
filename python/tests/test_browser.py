"""A real browser (headless Chromium) loads the HTML page and a screenshot
shows both bodies: their fill colours are counted in the PNG's pixels.

Skipped, with a message, only where Chromium is not installed
(``apt-get install chromium``; python/ci.sh installs it)."""

from __future__ import annotations

import shutil
import struct
import subprocess
import zlib
from pathlib import Path

import pytest

import ccd_exact as ccd
from conftest import SCENES

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="Chromium is not installed (apt-get install chromium): no browser test"
)

# ccd-picture's COLOR_A and COLOR_B.
BODY_A = (0x3B, 0x6F, 0xD6)
BODY_B = (0x2C, 0xA2, 0x5F)


def decode_png(data: bytes):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit, non-interlaced
    RGB or RGBA PNG, as Chromium writes them."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (n,) = struct.unpack(">I", data[pos : pos + 4])
        kind, body = data[pos + 4 : pos + 8], data[pos + 8 : pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, color, _, _, interlace = header
    assert depth == 8 and color in (2, 6) and interlace == 0, header
    bpp = 3 if color == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * bpp : x * bpp + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def count(rows, rgb, tolerance=6):
    return sum(
        1 for row in rows for p in row if all(abs(p[k] - rgb[k]) <= tolerance for k in range(3))
    )


def screenshot(page: Path, tmp_path: Path, fragment: str = "") -> list:
    png = tmp_path / (page.stem + ".png")
    cmd = [
        CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        "--hide-scrollbars", f"--user-data-dir={tmp_path / 'profile'}", "--window-size=940,760",
        "--virtual-time-budget=3000", f"--screenshot={png}", page.resolve().as_uri() + fragment,
    ]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=180)
    assert png.exists(), f"no screenshot: {done.stderr[-2000:]}"
    return decode_png(png.read_bytes())[2]


def test_the_python_page_shows_both_bodies(tmp_path):
    r = ccd.collide_toml((SCENES[0].parent / "paper-example-5-1.toml").read_text())
    page = tmp_path / "example-5-1.html"
    page.write_text(r.to_html("Example 5.1"), encoding="utf-8")
    rows = screenshot(page, tmp_path)
    assert count(rows, BODY_A) > 1000 and count(rows, BODY_B) > 1000


def test_the_cli_page_shows_both_bodies_at_any_time(cli, tmp_path):
    page = tmp_path / "example-5-2.html"
    scene = SCENES[0].parent / "paper-example-5-2.toml"
    done = subprocess.run([cli, str(scene), "--html", str(page)], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    for fragment in ("#t=0", "#t=0.5", ""):
        rows = screenshot(page, tmp_path, fragment)
        assert count(rows, BODY_A) > 500 and count(rows, BODY_B) > 500, fragment


def test_the_check_can_fail(tmp_path):
    # The same page without its script draws no body: the counts see that.
    r = ccd.collide_toml((SCENES[0].parent / "paper-example-5-1.toml").read_text())
    page = tmp_path / "no-script.html"
    html = r.to_html()
    start = html.index("<script>\n")
    page.write_text(html[:start] + html[html.index("</script>", start) + 9 :], encoding="utf-8")
    rows = screenshot(page, tmp_path)
    assert count(rows, BODY_A) < 50 and count(rows, BODY_B) < 50
