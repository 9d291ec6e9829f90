"""Simulated plots without target ids (clutter) and the test fleets (fleets)."""
