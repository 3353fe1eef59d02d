"""mmvlab report's page, read as a browser and a reviewer would (tests/readback/report_browser.sh).

usage: report_page.py PAGE_DIR REFERENCE_DIR

PAGE_DIR holds report.html and report.json; REFERENCE_DIR holds check.json, modes.json,
place-sensors.json and frf.json printed by those commands on their own. Exits non-zero
with every problem listed.
"""
import base64
import html.parser
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

problems = []


def fail(msg):
    problems.append(msg)


class Page(html.parser.HTMLParser):
    """The page's tags that load anything, its ids and links, and its tables by section."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.images, self.links, self.ids, self.loaders = [], [], set(), []
        self.tables = {}  # section id -> [table: [row: [cell text]]]
        self.section = None
        self.cell = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "section":
            self.section = a.get("id")
        if tag in ("script", "link", "iframe", "object", "embed", "video", "audio", "source", "base"):
            self.loaders.append(tag)
        if tag == "img":
            self.images.append(a.get("src", ""))
        if tag == "a":
            self.links.append(a.get("href", ""))
        if tag == "table":
            self.tables.setdefault(self.section, []).append([])
        if tag == "tr":
            self.tables[self.section][-1].append([])
        if tag in ("td", "th"):
            self.cell = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.cell is not None:
            self.tables[self.section][-1][-1].append(self.cell)
            self.cell = None

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data


def png_size(data):
    """(width, height) of a whole PNG, else None."""
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR" or data[-8:] != b"IEND\xaeB`\x82":
        return None
    return struct.unpack(">II", data[16:24])


def check_static(page_html, figures):
    p = Page()
    p.feed(page_html)
    if p.loaders:
        fail(f"tags that load or run something: {sorted(set(p.loaders))}")
    if re.search(r"https?:|url\(|src=\"//|href=\"//", page_html):
        fail("a remote reference in the page")
    decoded = 0
    for src in p.images:
        if not src.startswith("data:image/png;base64,"):
            fail(f"an image not inlined as a PNG: {src[:60]}")
            continue
        size = png_size(base64.b64decode(src.split(",", 1)[1], validate=True))
        if not size or min(size) < 100:
            fail(f"an inlined figure that is not a whole PNG of a useful size: {size}")
        else:
            decoded += 1
    if decoded != figures:
        fail(f"{decoded} whole figures in the page, report.json says {figures}")
    for href in p.links:
        if not href.startswith("#") or href[1:] not in p.ids:
            fail(f"a link that goes nowhere in the page: {href}")
    return p


def check_tables(p, ref):
    fmt = lambda x: "-" if x is None else "%.4g" % x
    modes = p.tables.get("modes", [[]])[0][1:]
    want = [fmt(m["frequency_hz"]) for m in ref["modes"]["modes"]]
    if [r[1] for r in modes] != want:
        fail(f"mode table frequencies {[r[1] for r in modes]} are not modes --json's {want}")
    check = p.tables.get("check", [[]])[0][1:]
    want = [(l["verdict"], l["requirement"], fmt(l["demand"]), fmt(l["margin_pct"])) for l in ref["check"]["lines"]]
    if [(r[0], r[2], r[3], r[6]) for r in check] != want:
        fail("the check table is not check --json's lines")
    sensors = p.tables.get("sensors", [[]])[0][1:]
    want = [(c["station"], c["axis"], fmt(c["score"])) for c in ref["place-sensors"]["chosen"]]
    if [(r[1], r[2], r[7]) for r in sensors] != want:
        fail(f"the sensor table is not place-sensors --json's choice: {sensors[:2]} against {want[:2]}")
    frf = p.tables.get("frf", [[]])[0][1:]
    want = [(q["output"], q["input"], fmt(q["peak_hz"]), fmt(q["peak_db"])) for q in ref["frf"]["pairs"]]
    if [(r[0], r[1], r[3], r[4]) for r in frf] != want:
        fail("the frequency-response table is not frf --json's pairs")


def check_isolator_tables(p, ref):
    """A HAM-SAS page: the measured features, the modes, the sensors and the
    transmissibility at 10 Hz are modes, place-sensors and frf --json's."""
    fmt = lambda x: "-" if x is None else "%.4g" % x
    tables = p.tables.get("modes", [])
    if len(tables) != 2:
        fail(f"the modes part has {len(tables)} tables, not the features' and the modes'")
        return
    features, modes = tables[0][1:], tables[1][1:]
    want = [(f["feature"], fmt(f["measured_hz"]), fmt(f["model_hz"]) if f["model_hz"] is not None else "none")
            for f in ref["modes"]["features"]]
    if [(r[0], r[1], r[2]) for r in features] != want:
        fail(f"the feature table is not modes --json's features: {features[:2]} against {want[:2]}")
    want = [fmt(m["frequency_hz"]) for m in ref["modes"]["modes"]]
    if [r[1] for r in modes] != want:
        fail(f"mode table frequencies {[r[1] for r in modes]} are not modes --json's {want}")
    sensors = p.tables.get("sensors", [[]])[0][1:]
    want = [(c["station"], c["axis"], fmt(c["score"])) for c in ref["place-sensors"]["chosen"]]
    if [(r[1], r[2], r[7]) for r in sensors] != want:
        fail(f"the sensor table is not place-sensors --json's choice: {sensors[:2]} against {want[:2]}")
    frf = p.tables.get("frf", [[]])[0][1:]
    at10 = ref["frf"]["at_10_hz_db"]
    want = ["%.1f" % at10[k][k] for k in range(6)]
    if [r[4] for r in frf] != want:
        fail(f"the transmissibility at 10 Hz {[r[4] for r in frf]} is not frf --json's {want}")


# The page's own chatter aside, Chromium itself asks Google for updates and accounts:
# a request counts as the page's when its network isolation key is the file:// page's.
CHROMIUM = ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--hide-scrollbars",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--disable-default-apps", "--disable-extensions", "--no-default-browser-check",
            "--host-resolver-rules=MAP * ~NOTFOUND", "--enable-logging=stderr", "--v=0",
            "--virtual-time-budget=10000"]


def chromium(url, work, *extra):
    profile = tempfile.mkdtemp(dir=work)
    r = subprocess.run(CHROMIUM + [f"--user-data-dir={profile}", *extra, url], capture_output=True, text=True,
                       timeout=120)
    shutil.rmtree(profile, ignore_errors=True)
    return r


def page_requests(netlog):
    d = json.load(open(netlog))
    start = d["constants"]["logEventTypes"]["URL_REQUEST_START_JOB"]
    out = []
    for e in d["events"]:
        params = e.get("params", {})
        if e["type"] == start and "file://" in params.get("network_isolation_key", ""):
            if not params.get("url", "").startswith(("file:", "data:")):
                out.append(params["url"])
    return out


def non_blank(png):
    """Share of pixels that are not the page's white, and how many colours there are."""
    import vtk  # Debian's python3-vtk9 (./setup.sh --test)
    from vtk.util.numpy_support import vtk_to_numpy
    r = vtk.vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    img = r.GetOutput()
    px = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3]
    ink = (px < 245).any(axis=1).mean()
    colours = len({tuple(c) for c in px[:: max(1, len(px) // 20000)]})
    return img.GetDimensions()[:2], ink, colours


CHECKER = """<script>
window.addEventListener('load', () => {
  const imgs = [...document.images];
  const broken = imgs.filter(i => !i.complete || i.naturalWidth === 0).length;
  console.log(`mmvlab-page images=${imgs.length} broken=${broken} sections=${document.querySelectorAll('main > section').length} width=${document.documentElement.scrollWidth}`);
});
</script>"""


def browse(page, work, figures, sections, shot_size=(1280, 2400)):
    """The page in Chromium: (problems, facts). The page unchanged must log nothing and ask
    for nothing; a copy with a checker script (the page's policy widened for it alone)
    counts its images and broken ones."""
    found = []
    url = "file://" + os.path.abspath(page)
    netlog, shot = os.path.join(work, "net.json"), os.path.join(work, "shot.png")
    r = chromium(url, work, f"--log-net-log={netlog}", f"--screenshot={shot}",
                 f"--window-size={shot_size[0]},{shot_size[1]}")
    console = [l for l in r.stderr.splitlines() if ":CONSOLE" in l]
    if console:
        found.append(f"console messages: {console[:3]}")
    requests = page_requests(netlog)
    if requests:
        found.append(f"requests from the page: {requests[:3]}")
    if not os.path.exists(shot):
        found.append(f"no screenshot: {r.stderr[-500:]}")
    else:
        dims, ink, colours = non_blank(shot)
        if tuple(dims) != shot_size or ink < 0.1 or colours < 100:
            found.append(f"a blank-looking screenshot: {dims}, {ink:.3f} of the pixels inked, {colours} colours")
    text = open(page, encoding="utf-8").read()
    checked = os.path.join(work, "checked.html")
    with open(checked, "w", encoding="utf-8") as f:
        f.write(text.replace("default-src 'none';", "default-src 'none'; script-src 'unsafe-inline';")
                .replace("</body>", CHECKER + "</body>"))
    r = chromium("file://" + checked, work, "--dump-dom", f"--window-size={shot_size[0]},{shot_size[1]}")
    m = re.search(r"mmvlab-page images=(\d+) broken=(\d+) sections=(\d+) width=(\d+)", r.stderr)
    if not m:
        found.append(f"the checker did not run: {r.stderr[-500:]}")
        return found
    images, broken, shown, width = map(int, m.groups())
    if images != figures or broken or int(m.group(3)) != sections or width > shot_size[0]:
        found.append(f"in the browser: {images} images ({figures} expected), {broken} broken, {shown} sections ({sections}), "
                     f"{width} px wide at {shot_size[0]}")
    return found


def main():
    page_dir, ref_dir = sys.argv[1], sys.argv[2]
    page = os.path.join(page_dir, "report.html")
    doc = json.load(open(os.path.join(page_dir, "report.json")))
    isolator = "check" not in doc  # a HAM-SAS page: no check part
    verbs = ("modes", "place-sensors", "frf") if isolator else ("check", "modes", "place-sensors", "frf")
    ref = {v: json.load(open(os.path.join(ref_dir, v + ".json"))) for v in verbs}
    sections = 5 if isolator else 7  # the article: renders, check, strength, modes, sensors, frf, scene
    text = open(page, encoding="utf-8").read()
    p = check_static(text, doc["figures"])
    (check_isolator_tables if isolator else check_tables)(p, ref)
    work = tempfile.mkdtemp()
    try:
        for f in browse(page, work, doc["figures"], sections):
            fail(f)
        pdf = os.path.join(work, "report.pdf")
        chromium("file://" + os.path.abspath(page), work, f"--print-to-pdf={pdf}", "--no-pdf-header-footer")
        data = open(pdf, "rb").read() if os.path.exists(pdf) else b""
        pages = re.findall(rb"/Type\s*/Page[^s]", data)
        if not data.startswith(b"%PDF") or not 4 <= len(pages) <= 80:
            fail(f"printing to PDF: {len(data)} bytes, {len(pages)} pages")
        # The checks can see what they are for: a remote image and a broken figure (shown
        # once per run: a second page, --positive-only, skips it).
        if "--positive-only" not in sys.argv[3:]:
            bad = os.path.join(work, "bad.html")
            with open(bad, "w", encoding="utf-8") as f:
                f.write(text.replace("<main>", '<main><img alt="remote" src="https://example.com/x.png">'
                                               '<img alt="broken" src="data:image/png;base64,iVBORw0KGgo=">', 1))
            caught = browse(bad, work, doc["figures"] + 2, sections)
            for what in ("console messages", "2 broken"):
                if not any(what in c for c in caught):
                    fail(f"a page with a remote image and a broken figure was not caught ({what}): {caught}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if problems:
        print("report page:\n  " + "\n  ".join(problems))
        sys.exit(1)
    print(f"report page: {doc['figures']} figures, {len(p.ids)} ids, tables equal to the commands' JSON, "
          f"clean in Chromium, printed to {len(pages)} PDF pages")


main()
