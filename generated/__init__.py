"""GENERATED FILE - DO NOT EDIT BY HAND. Produced by `python -m derive` from the sympy derivations in derive/. Edit derive/ and regenerate; `python -m derive --check` verifies freshness.

Data package holding the generated CasADi artifacts."""
