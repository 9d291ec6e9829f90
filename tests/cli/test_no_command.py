"""``registration`` without a command lists the commands (on standard error) and exits 2."""

from __future__ import annotations

from registration.cli import COMMANDS, main


def test_no_command_lists_the_commands_and_exits_2(capsys):
    assert main([]) == 2
    err = capsys.readouterr().err
    assert "usage: registration" in err
    for name in ("simulate", "fleet", "import", "serve", "replay"):
        assert name in COMMANDS and f"    {name}" in err, name
