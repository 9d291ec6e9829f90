"""Interoperation with other frameworks: Stone Soup
(:mod:`registration.interop.stonesoup`, needs Stone Soup: ``pip install stonesoup``)."""
