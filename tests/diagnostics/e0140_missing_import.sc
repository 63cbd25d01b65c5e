// The imported file does not exist: the hint lists where it was looked for.
import "imports/no_such_file.sc";
chart Main { initial S; state S; }
