"""Interoperation with other frameworks: Stone Soup (:mod:`registration.interop.stonesoup`, needs ``pip install "sensor-registration[stonesoup]"``)."""
