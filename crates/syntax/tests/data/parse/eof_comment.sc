const X = 1;
// comment at EOF with no newline