4(ÿş bad Ã( bytes â‚)
G00 X0 ĞŸĞ 
€
