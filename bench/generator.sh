#!/usr/bin/env bash
# Generator benchmark: Monas C++ generation for a model of about 1,000 states,
# against plain file writes measured in the same run.
exec "$(dirname "$0")/run-java.sh" org.kse.benchmarks.GeneratorBenchmark
