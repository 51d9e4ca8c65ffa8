#!/usr/bin/env bash
# Diagram server benchmark, over its WebSocket on loopback: open a 1,000-state statechart without
# a notation file (ELK arranges it), and the round trip of moving a state of a 500-state model
# (median and p95), each with a baseline measured in the same run.
exec "$(dirname "$0")/run-java.sh" org.kse.benchmarks.DiagramBenchmark
