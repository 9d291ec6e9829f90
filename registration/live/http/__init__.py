"""What the live service answers over HTTP: the snapshot of estimates, status and history
(:mod:`.api`), the read-only server (:mod:`.server`) and the page's files (:mod:`.assets`)."""
