"""unity stage."""
