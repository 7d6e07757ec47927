"""Tests of the unity stage: scene patcher, .meta files, project index."""
