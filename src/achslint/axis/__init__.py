"""One axis: typed values from the parsed lines (`analysis`, `facts`), the corrections the CNC makes when it
loads them (`corrections`), and the resolved axis every command reads (`resolved`)."""
