"""Access to the generated functions (``generated/``): artifact lookup and hash checks, the
compiled C backend and the serialized CasADi fallback. Only the runtime uses it; users call the
capability subpackages."""

from registration._codegen.loader import ArtifactError, BoundCall, GeneratedFunction, backend, generated_dir, get, manifest

__all__ = ["ArtifactError", "BoundCall", "GeneratedFunction", "backend", "generated_dir", "get", "manifest"]
