// E0005: a source file that is not UTF-8 (a Latin-1 é in this comment).
chart M { initial S; state S; }
