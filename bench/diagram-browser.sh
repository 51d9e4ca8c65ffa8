#!/usr/bin/env bash
# Diagram editor benchmark in headless Chromium against kse serve (as the end-to-end tests run
# it): open a 1,000-state statechart (request to drawn), move a state in it (mouse-up to redrawn,
# 30 moves, median and p95) and the same move in the 47-state Goalie as the baseline. Prints the
# figures; never fails on one.
exec "$(dirname "$0")/../tests/org.kse.diagram.e2e/run.sh" --script bench/browser.bench.mjs
