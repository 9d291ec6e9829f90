"""Decoded records made into the fleet tables: the time axis (timeofday), each record's verdict
(verdicts), CAT048 plots (plots48), CAT021 references (adsb21), CAT034 scan periods and clock check
(service), SITES.csv (sites), the fleet files' columns and the tables SITES gives (fleetfiles), one
file's rows (assemble), the summary."""
