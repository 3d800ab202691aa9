"""Text to lines: the list grammar (`parser`), the CNC's number forms (`numbers`), lists inside XML (`xmlinput`)."""
