"""Tests of the ASTERIX reader (registration.io.asterix); fixtures encoded with libasterix."""
