% Reads every CSV named on the command line in Octave as MATLAB users do: each header
% name must be a valid variable name (readtable renames those that are not), and the
% numbers read by csvread below the header must fill as many rows as the file has.
% Prints 'N passed, N failed'.
args = argv();
passed = 0; failed = 0;
for k = 1:numel(args)
  f = args{k};
  fid = fopen(f, 'r');
  header = strsplit(fgetl(fid), ',');
  lines = 0;
  while ischar(fgetl(fid)); lines = lines + 1; end
  fclose(fid);
  ok = all(cellfun(@isvarname, header));
  if lines > 0
    d = csvread(f, 1, 0);
    ok = ok && size(d, 1) == lines && size(d, 2) <= numel(header);
  end
  if ok
    passed = passed + 1;
  else
    failed = failed + 1;
    bad = header(~cellfun(@isvarname, header));
    printf('%s: not read as it is (names: %s)\n', f, strjoin(bad, ' '));
  end
end
printf('%d passed, %d failed\n', passed, failed);
if failed > 0
  error("%d CSV files not read as they are", failed);
end
