#!/usr/bin/env bash
# mmvlab report's page in a real browser: Debian's chromium, headless, loads report.html
# from the slew scene; the page must make no console message and no request, every
# figure must decode, the screenshot must not be blank, and it must print to a PDF. The
# page's tables are compared with what check, modes, place-sensors and frf print on their
# own. The same checks must catch a page with a remote image and a broken figure. Then
# the same for the HAM-SAS scene's page (the checks' own check once is enough).
# ctest runs it; by hand: tests/readback/report_browser.sh build/mmvlab
source "$(dirname "$0")/prelude.sh"
command -v chromium >/dev/null || { echo "chromium is not installed (./setup.sh --test installs it)"; exit 1; }
scene=scenes/mmv-slew.yaml
run page report "$scene" --segments 4
"$bin" check "$scene" --segments 4 --json --report-only >"$tmp/check.json"  # its joint 1 FAILs: exit 3 without it
for verb in modes frf; do "$bin" "$verb" "$scene" --segments 4 --json >"$tmp/$verb.json"; done
"$bin" place-sensors "$scene" --segments 4 --below-hz 50 --count 8 --json >"$tmp/place-sensors.json"
/usr/bin/python3 "$here/report_page.py" "$tmp/page" "$tmp"
# HAM-SAS: the isolator's page (no check part), against modes, place-sensors (modes below
# 5 Hz, 12 sensors: the report's defaults for an isolator) and frf on their own.
scene=scenes/hamsas.yaml
run hpage report "$scene"
mkdir -p "$tmp/href"
for verb in modes frf; do "$bin" "$verb" "$scene" --json >"$tmp/href/$verb.json"; done
"$bin" place-sensors "$scene" --below-hz 5 --count 12 --json >"$tmp/href/place-sensors.json"
/usr/bin/python3 "$here/report_page.py" "$tmp/hpage" "$tmp/href" --positive-only
