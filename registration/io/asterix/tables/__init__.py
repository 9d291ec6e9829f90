"""Decoded records made into the fleet tables: the time axis (timeofday), each record's verdict
(verdicts), CAT048 plots (plots48), CAT021 references (adsb21), CAT034 scan periods and clock check
(service), SITES.csv (sites) and the tables it gives (tables), one file's rows (assemble), the summary."""
