"""Tests of registration.interop (Stone Soup)."""
