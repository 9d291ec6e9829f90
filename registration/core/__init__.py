"""Shared core: frames and geodesy, angles, input validation, time alignment, observability.

Every capability subpackage builds on these modules; nothing here imports a capability.
"""
