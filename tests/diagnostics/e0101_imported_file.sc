// The unknown name is in the imported file; the diagnostic shows that file's source.
import "imports/bad_chart.sc";
system Main { instance b: Bad; }
