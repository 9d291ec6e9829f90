"""``registration fleet``: the sub-command (``command``: ``fleet simulate``, ``fleet register``) and
its parts: the option table (``options``), opening ``--tables`` (``tables``), the outputs of a run
in memory (``output``), of an archive run (``archive``, ``archive_output``) and of the association
(``association``)."""

from registration.cli.fleet.command import HELP, REGISTER_OUTPUTS, SIMULATE_OUTPUTS, add_arguments, run

__all__ = ["HELP", "REGISTER_OUTPUTS", "SIMULATE_OUTPUTS", "add_arguments", "run"]
