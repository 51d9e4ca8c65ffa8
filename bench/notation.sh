#!/usr/bin/env bash
# Notation benchmark: open a statechart of about 1,000 states without a notation file and
# arrange it with ELK. Prints medians and the ratio against loading the model alone.
exec "$(dirname "$0")/run-java.sh" org.kse.benchmarks.NotationBenchmark
