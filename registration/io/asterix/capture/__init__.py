"""Where the ASTERIX data blocks are in a file: content detection and gzip (capture), pcap and pcapng
packets (pcap), their UDP datagrams (netstack), the data blocks in each (blocks)."""
