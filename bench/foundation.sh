#!/usr/bin/env bash
# Foundation benchmark: transform, validate, label and load+save a model built from
# formulas with 10,000 activities. Prints medians and ratios against baselines.
exec "$(dirname "$0")/run-java.sh" org.kse.benchmarks.FoundationBenchmark
